#pragma once
// The static map (issue: a map of the static world without ghosts of passers-by): Slam's
// keyframes (a KeyFrameObserver) fused into a VoxelMap in the odometry (world) frame.
//
// - Each new keyframe's depth is back-projected (BackProjectKeyFrame) without the pixels of
//   moving objects (DynamicPixelMask, map.dynamic_masks) and kept in its optical frame while the
//   keyframe is in Slam's window, so that the back end's pose corrections move its points.
// - When it leaves the window (or at a reset with kKeepPose, or FuseWindow), its pose is final
//   and it is fused for good. With map.free_space_check, first its depth checks the voxels hit
//   by the map.free_space_keyframes keyframes before it (a voxel it sees through gains a miss;
//   transient voxels are removed: VoxelMap::Carve), then the depth images of those keyframes
//   vote on each of its points (transient points are not fused), then the survivors are fused,
//   and the map is cropped to the cube of half-side map.extent_m around its camera (the memory
//   bound).
// - A reset with kNewWorld empties everything.
// - A loop correction (OnCorrection) moves the window's keyframes to their corrected poses and
//   re-fuses the map: the fused points of the newest tracking.max_keyframes fused keyframes are
//   kept in their optical frames (about 16 bytes per point, a few thousand points per keyframe),
//   so the voxels are rebuilt from them at the corrected poses (a keyframe the map no longer has
//   moves with the nearest older one it has; points whose voxels were carved or cropped since
//   stay out), and a wall seen
//   before and after the loop is one wall, not two.
//
// Threads: the observer calls come from one thread at a time (Slam's contract); Cloud, stats,
// revision and FuseWindow may be called from any thread. One mutex guards the state; it is never
// held while calling out, and Slam never holds its map mutex while calling in.

#include <cstdint>
#include <deque>
#include <mutex>
#include <vector>

#include "dslam/backend/keyframe_observer.h"
#include "dslam/core/config.h"
#include "dslam/mapping/coloured_cloud.h"
#include "dslam/mapping/free_space.h"
#include "dslam/mapping/occupancy_grid.h"
#include "dslam/mapping/voxel_map.h"

namespace dslam {

/// Counts of a static map.
struct StaticMapStats {
  size_t voxels = 0;            ///< voxels fused for good
  int window_keyframes = 0;     ///< keyframes kept in their optical frame (Slam's window)
  int fused_keyframes = 0;      ///< keyframes fused for good since the last kNewWorld reset
  size_t transient_points = 0;  ///< keyframe points not fused: other keyframes saw through them
  size_t carved_voxels = 0;     ///< voxels removed as transient
  size_t cropped_voxels = 0;    ///< voxels removed outside the extent
  int corrections = 0;          ///< loop corrections that re-fused the map
};

/// What an occupancy grid is made of (BuildOccupancyGrid), world (odometry) frame.
struct StaticMapRays {
  /// [m] the points of the map fused for good (one per voxel): not the window's, whose people
  /// the free-space check has not seen through yet (a walker in the newest keyframes).
  std::vector<Eigen::Vector3f> points_world;
  /// The rays of the keyframes whose points the mapper keeps: the newest tracking.max_keyframes
  /// fused ones (their fused points) and the window's (their points), oldest first.
  std::vector<GridView> views;
};

/// The occupancy grid of `rays` (StaticMapper::Rays) with up `up_world` (world frame) and cells of
/// config.grid.cell_size_m, or of the map's voxel (map.voxel_size_m) when that is 0. The world is
/// the tracker's, the first frame's optical frame: the grid's reference camera.
OccupancyGrid GridOf(const StaticMapRays& rays, const Eigen::Vector3d& up_world,
                     const Config& config);

/// Fuses Slam's keyframes into a static map (see above).
class StaticMapper : public KeyFrameObserver {
 public:
  /// Uses config.map, config.dynamic_mask and config.depth_noise's depth range (depths outside
  /// are not fused and get no free-space vote). Throws ConfigError
  /// when `config` is invalid.
  explicit StaticMapper(const Config& config);

  void OnKeyFrames(const std::vector<KeyFrameRecord>& added,
                   const std::vector<KeyFramePose>& window) override;
  void OnReset(ResetMode mode) override;
  /// Re-fuses the map at the corrected poses (top of this file).
  void OnCorrection(const std::vector<KeyFramePose>& keyframes) override;

  /// Fuses the window's keyframes for good, oldest first, at their current poses (the end of a
  /// run: nothing corrects them any more).
  void FuseWindow();

  /// The map in the world (odometry) frame: one point per voxel of the fused map, and the window
  /// keyframes' points at their current poses, one per voxel not yet in the fused map.
  ColouredCloud Cloud() const;

  /// The map's points fused for good and the rays of the keyframes it keeps (the window's
  /// too), at their current poses.
  StaticMapRays Rays() const;

  StaticMapStats stats() const;
  /// Increases whenever the map changes (a keyframe, a pose, a reset).
  uint64_t revision() const;

 private:
  /// A keyframe of Slam's window: its points in its optical frame and its depth for the check.
  struct WindowKeyFrame {
    int id = -1;
    Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
    ColouredCloud points_camera;  ///< [m] optical frame
    DepthView view;
  };

  /// A keyframe fused for good: its fused points in its optical frame, for re-fusion.
  struct FusedKeyFrame {
    int id = -1;
    Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
    ColouredCloud points_camera;  ///< [m] optical frame
  };
  WindowKeyFrame Prepare(const KeyFrameRecord& keyframe) const;  ///< no lock needed
  void FuseForGood(WindowKeyFrame keyframe);                     ///< lock held
  /// Keeps `points_world` of keyframe `id` for re-fusion (in its optical frame); lock held.
  void KeepFused(int id, const Eigen::Isometry3d& T_world_camera,
                 const ColouredCloud& points_world);
  /// The points of `keyframe` that the views of earlier fused keyframes do not see through.
  ColouredCloud CheckedPoints(const WindowKeyFrame& keyframe);  ///< lock held

  const MapConfig config_;
  const DynamicMaskConfig mask_config_;
  const FreeSpaceTolerance tolerance_;
  const double min_depth_m_;              ///< [m] depth_noise.min_depth_m
  const BackProjection back_projection_;  ///< how a keyframe's depth is sampled (Of the config)
  mutable std::mutex mutex_;              ///< guards everything below
  VoxelMap voxels_;
  std::deque<WindowKeyFrame> window_;  ///< oldest first
  std::deque<DepthView> views_;        ///< of the latest fused keyframes, oldest first
  const size_t max_fused_kept_;        ///< tracking.max_keyframes
  std::deque<FusedKeyFrame> fused_;    ///< the newest fused keyframes, oldest first
  StaticMapStats stats_;
  uint64_t revision_ = 0;
};

}  // namespace dslam
