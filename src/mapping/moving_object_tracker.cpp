#include "dslam/mapping/moving_object_tracker.h"

#include <algorithm>
#include <utility>

#include "dslam/core/side_by_side.h"
#include "dslam/mapping/region_join.h"
#include "dslam/mapping/region_split.h"

namespace dslam {

MovingObjectTracker::MovingObjectTracker(const Config& config)
    : mask_config_(config.dynamic_mask),
      objects_config_(config.objects),
      depth_noise_(config.depth_noise),
      tracker_(config.objects),
      reference_(config.dynamic_mask, config.depth_noise),
      carrier_(config.objects, config.dynamic_mask) {}

CarriedFlow MovingObjectTracker::MaskAndFlow(const RgbdFrame& frame, const FrameResult& result,
                                             const std::vector<Eigen::Vector3d>& predicted) {
  // The carried points' flow needs no mask: it runs beside the mask's computation. Neither
  // touches the other's state.
  CarriedFlow flow;
  RunSideBySide(
      [&] {
        mask_ = ComputeDynamicMask(frame, result.T_world_camera, result.points, mask_config_,
                                   predicted, objects_config_.gate_m,
                                   objects_config_.track_min_points, &reference_);
      },
      [&] { flow = carrier_.Track(frame, result.points); });
  return flow;
}

std::vector<TrackedObject> MovingObjectTracker::Process(const RgbdFrame& frame,
                                                        const FrameResult& result) {
  if (result.reset) Reset();
  if (!result.has_pose) {
    carrier_.Reset();  // the next frame is not consecutive to the last one carried from
    return {};
  }
  if (!history_.empty() && !(result.stamp_s > history_.back().stamp_s)) {
    history_.clear();
    carrier_.Reset();
  }
  const std::vector<Eigen::Vector3d> predicted = tracker_.PredictedPositions(result.stamp_s);
  CarriedFlow flow = MaskAndFlow(frame, result, predicted);
  reference_.Add(frame, result.T_world_camera, result.stamp_s);
  carrier_.Attach(std::move(flow), frame, result.T_world_camera, result.points, &mask_);
  SplitRegions(frame, result.T_world_camera, history_, result.stamp_s, predicted, mask_config_,
               objects_config_, &mask_);
  JoinStackedRegions(mask_config_, objects_config_, &mask_);
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
