#pragma once
// The moving objects of each frame, from its FrameResult: the dynamic mask (dynamic_mask.h) of
// the frame's unmarked points and the depth change against recent frames (depth_change.h); the
// points of the previous frame's regions that the front end lost, carried into its regions by
// optical flow (point_carrier.h); its regions split where two things move differently
// (region_split.h) and joined where they are parts of one thing (region_join.h); the regions as
// observations, and the tracker (object_tracker.h).
// Runs after Slam::ProcessFrame on one thread, frame by frame in order: the objects' own thread
// (OrderedWorker, in dslam_run_dataset --threads and the node with ~backend_threads) or the thread
// that consumes FrameResults.

#include <deque>
#include <vector>

#include "dslam/core/config.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/mapping/depth_change.h"
#include "dslam/mapping/dynamic_mask.h"
#include "dslam/mapping/object_tracker.h"
#include "dslam/mapping/point_carrier.h"
#include "dslam/tracking/frame_result.h"

namespace dslam {

/// Dynamic mask and object tracking, frame by frame (one thread).
class MovingObjectTracker {
 public:
  /// Uses config.dynamic_mask and config.objects (validated by the caller's Config::Validate).
  explicit MovingObjectTracker(const Config& config);

  /// The objects of `frame` from its `result` (result.points must be filled: FrameRequest
  /// points). Lost frames (no pose) return nothing and leave the tracks as they are (no point is
  /// carried across them); a reset result (FrameResult::reset) forgets them first.
  std::vector<TrackedObject> Process(const RgbdFrame& frame, const FrameResult& result);

  /// The dynamic mask of the last frame Process was given with a pose (empty before).
  const DynamicMask& last_mask() const { return mask_; }

  /// Forgets the tracks (Slam::Reset).
  void Reset() {
    tracker_.Reset();
    history_.clear();
    reference_.Clear();
    carrier_.Reset();
  }

 private:
  /// Computes mask_ for `frame` and, beside it, the carried points' flow (PointCarrier::Track).
  CarriedFlow MaskAndFlow(const RgbdFrame& frame, const FrameResult& result,
                          const std::vector<Eigen::Vector3d>& predicted);

  DynamicMaskConfig mask_config_;
  ObjectsConfig objects_config_;
  DepthNoiseConfig depth_noise_;  ///< for the observations' motion_sigma_mps
  ObjectTracker tracker_;
  DynamicMask mask_;
  std::deque<PointPositions> history_;  ///< recent frames' unmarked points, oldest first
  /// Recent frames' depth for the depth-change seeds.
  DepthReference reference_;
  PointCarrier carrier_;  ///< lost points of the regions, by optical flow
};

}  // namespace dslam
