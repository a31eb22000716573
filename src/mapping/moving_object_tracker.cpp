#include "dslam/mapping/moving_object_tracker.h"

#include <algorithm>

#include "dslam/mapping/region_split.h"

namespace dslam {

MovingObjectTracker::MovingObjectTracker(const Config& config)
    : mask_config_(config.dynamic_mask),
      objects_config_(config.objects),
      depth_noise_(config.depth_noise),
      tracker_(config.objects),
      reference_(config.dynamic_mask, config.depth_noise) {}

std::vector<TrackedObject> MovingObjectTracker::Process(const RgbdFrame& frame,
                                                        const FrameResult& result) {
  if (result.reset) Reset();
  if (!result.has_pose) return {};
  const std::vector<Eigen::Vector3d> predicted = tracker_.PredictedPositions(result.stamp_s);
  mask_ = ComputeDynamicMask(frame, result.T_world_camera, result.points, mask_config_, predicted,
                             objects_config_.gate_m, objects_config_.track_min_points,
                             mask_config_.depth_change_seeds ? &reference_ : nullptr);
  if (mask_config_.depth_change_seeds) reference_.Add(frame, result.T_world_camera, result.stamp_s);
  if (!history_.empty() && !(result.stamp_s > history_.back().stamp_s)) history_.clear();
  SplitRegions(frame, result.T_world_camera, history_, result.stamp_s, predicted, mask_config_,
               objects_config_, &mask_);
  std::vector<ObjectObservation> observations =
      ObservationsFromMask(mask_, objects_config_, result.stamp_s, history_, &depth_noise_,
                           result.T_world_camera.translation(), predicted);
  history_.push_back(PositionsOf(mask_, result.stamp_s));
  while (result.stamp_s - history_.front().stamp_s >
         std::max(objects_config_.velocity_baseline_s, objects_config_.motion_baseline_s))
    history_.pop_front();
  return tracker_.Update(result.stamp_s, observations);
}

}  // namespace dslam
