#pragma once
// One run of the back end's local mapping after a keyframe (paper Sec. V): static point
// determination over the window (Algorithm 1, window_static_points.h), then local bundle
// adjustment (local_bundle_adjustment.h), on a copy of the keyframe window. The copy lets
// tracking go on with the live map while the run works: the constructor copies and Apply writes
// the results back, both under the caller's map lock; Run needs no lock. Run on an untouched map,
// copy, run and apply give the same map as running in place.

#include <cstdint>
#include <unordered_map>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/core/config.h"
#include "dslam/tracking/frame_result.h"
#include "dslam/tracking/map.h"

namespace dslam {

class LocalMappingJob {
 public:
  /// Copies the window of `map` (Map::WindowCopy) and remembers each copied point's position
  /// and mark. `generation` identifies the map it came from (Slam's reset counter).
  LocalMappingJob(const Map& map, uint64_t generation);

  /// Static point determination (when static points are on),
  /// then local BA, on the copy. Fills status() but for window_keyframes.
  void Run(const Config& config);

  /// Writes the run's results to `map`, which tracking may have changed since the copy, for the
  /// keyframes and points still in it and not frozen (Map::Freeze):
  /// - keyframe poses of the copied window; keyframes made since the copy, and the points they
  ///   made, move rigidly with the window's newest keyframe (correction());
  /// - positions of the points the run moved: the run's position where tracking left the point
  ///   as copied; the run's displacement added where tracking moved a marked point (fusion);
  ///   tracking's position where it moved an unmarked point (it follows its object);
  /// - points the run unmarked are unmarked in `map` (MapPoint::Unmark with
  ///   tracking.remark_frames), on top of what tracking counted meanwhile.
  /// Positions and poses are left alone when local BA was rejected, and when `map` was
  /// corrected (Map::MoveMadeSince) since the copy: the run's poses are in the world before the
  /// correction; its unmarks still apply.
  void Apply(Map* map) const;

  /// [world_new <- world_old] How the run moved the copied window's newest keyframe,
  /// T_world_camera_refined * T_world_camera_copied^-1; identity when no keyframe moved.
  Eigen::Isometry3d correction() const;

  const BackEndStatus& status() const { return status_; }
  uint64_t generation() const { return generation_; }
  /// Id of the newest keyframe of the copied window (-1: none).
  int newest_keyframe_id() const { return newest_keyframe_id_; }
  /// Whether Apply changed keyframe poses (local BA ran and was applied).
  bool moved_keyframes() const { return status_.ba.ran && !status_.ba.rejected; }

 private:
  struct PointBefore {
    Eigen::Vector3d p_world;
    bool marked;
  };

  /// The run's unmarks and, with `move_points`, its point positions, written to `map`.
  void ApplyToPoints(Map* map, bool move_points) const;
  /// Moves the keyframes made since the copy, and the points they made, by correction().
  void MoveWhatWasMadeSince(Map* map) const;

  Map window_;
  uint64_t generation_;
  int newest_keyframe_id_ = -1;
  Eigen::Isometry3d T_world_newest_copied_ = Eigen::Isometry3d::Identity();
  PointId first_new_point_id_ = 0;     ///< points with ids from here on were made after the copy
  uint64_t map_corrections_ = 0;       ///< Map::corrections() of the copied map
  int unmark_min_dynamic_frames_ = 0;  ///< tracking.remark_frames of the run
  std::unordered_map<PointId, PointBefore> before_;
  BackEndStatus status_;
};

}  // namespace dslam
