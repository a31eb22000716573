#pragma once
// Depth-change seeds of the dynamic mask: where the depth of a frame came clearly nearer than what
// recent frames saw along the same ray, something is there that was not there then (a person
// walking in front of the wall). These seeds find moving things whose sparse points the front end
// still marks (the first frames of a run, far people), which the unmarked points cannot seed.
//
// Prediction source: the recent frames themselves, not the static voxel map. A DepthReference
// keeps the depth of one frame every DynamicMaskConfig::depth_change_interval_s (the newest
// depth_change_references), each reduced to the mask's cells as a DepthView (free_space.h): per
// block of decimation x decimation pixels the depth of its centre pixel (the pixel the mask's
// cell takes its depth from), then the nearest of its 3x3 blocks, so depth edges and pose errors
// of a pixel or two give occlusion, not a change. The voxel map is not used: it is fused on the
// back-end thread from keyframes leaving Slam's window (seconds late, empty in the first frames
// where the seeds matter most) and contains the people the unmarked points did not mask. A
// reference that saw a person where the person still is gives no vote; one that saw the wall
// where the person now stands does.
//
// Cost per frame (tracking thread): adding a reference reads one pixel per block and erodes the
// blocks (every depth_change_interval_s only; no pass over the full-size image); testing a frame
// projects the valid, unlabelled, unblocked cells on every kDepthChangeStride-th row and column
// (at most 80 x 60 of the 160 x 120 cells at 640 x 480, decimation 4, stride 2) into each
// reference until one sees through it (at most depth_change_references projections per cell).
// Measured: median_objects_ms of the run summaries (mask and tracking per frame) of
// dslam_run_dataset on scripts/mapping_benchmark.py's renders, with and without the seeds
// alternately, 2 rounds, a shared machine at load 3-5 on 2 cores: walking seed 1 1.03 ms without
// the seeds, 1.51 ms with them; close_person seed 1 0.96 and 1.21 ms; static_room seed 1 0.15 and
// 0.48 ms (p95 0.22 and 0.70 ms).

#include <deque>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/core/features_config.h"
#include "dslam/core/objects_config.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/mapping/free_space.h"

namespace dslam {

/// Only the cells on every kDepthChangeStride-th row and column are tested for depth change (each
/// stands for stride x stride cells in depth_change_min_cells); the growth fills the cells between.
constexpr int kDepthChangeStride = 2;

/// Recent frames' depth with their poses: what was seen before, for the depth-change test.
class DepthReference {
 public:
  /// Uses the depth_change_* fields and decimation of `mask` and the depth noise model `noise`
  /// (sigma_d, min_depth_m).
  DepthReference(const DynamicMaskConfig& mask, const DepthNoiseConfig& noise);

  /// Keeps `frame` (pose `T_world_camera`: optical frame -> world) stamped `stamp_s` [s] as a
  /// reference when no reference was kept within depth_change_interval_s before it; drops the
  /// oldest beyond depth_change_references. A stamp before the newest reference clears them first.
  void Add(const RgbdFrame& frame, const Eigen::Isometry3d& T_world_camera, double stamp_s);

  /// Whether some reference saw clearly beyond `p_world` [m, world frame], a point measured at
  /// depth `depth_m` [m] in the current frame: every depth of the reference around the point's
  /// pixel lies beyond it by more than depth_change_margin_m + depth_change_sigma_factor *
  /// sigma_d(depth_m).
  bool Changed(const Eigen::Vector3d& p_world, double depth_m) const;

  /// Changed() for the points of one frame, given in its optical frame: the references' poses
  /// relative to the frame are composed once. Valid while the DepthReference is not changed.
  class FrameTest {
   public:
    /// Changed(T_world_camera * p, p.z()) of each p of `points_camera` [m, optical frame]: 1
    /// where changed, 0 elsewhere. Tests the points against one reference before the next (its
    /// blocks stay in the cache), each only until one sees through it.
    std::vector<uint8_t> ChangedAll(const std::vector<Eigen::Vector3d>& points_camera) const;

   private:
    friend class DepthReference;
    const DepthReference* reference_ = nullptr;
    std::vector<Eigen::Isometry3f> T_view_camera_;  ///< per reference, newest first
  };
  /// The test of the frame at `T_world_camera` (optical frame -> world) [m].
  FrameTest ForFrame(const Eigen::Isometry3d& T_world_camera) const;

  bool empty() const { return views_.empty(); }
  int size() const { return static_cast<int>(views_.size()); }  ///< references kept
  void Clear() { views_.clear(); }

 private:
  /// The tolerance of a point measured at `depth_m` [m] (see Changed()).
  FreeSpaceTolerance Tolerance(double depth_m) const;

  DynamicMaskConfig mask_;
  DepthNoiseConfig noise_;
  std::deque<DepthView> views_;  ///< oldest first
  double last_stamp_s_ = 0.0;    ///< [s] of the newest reference
};

}  // namespace dslam
