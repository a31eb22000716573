#include "dslam/mapping/moving_object_tracker.h"

namespace dslam {

MovingObjectTracker::MovingObjectTracker(const Config& config)
    : mask_config_(config.dynamic_mask),
      objects_config_(config.objects),
      tracker_(config.objects) {}

std::vector<TrackedObject> MovingObjectTracker::Process(const RgbdFrame& frame,
                                                  const FrameResult& result) {
  if (result.reset) tracker_.Reset();
  if (!result.has_pose) return {};
  mask_ = ComputeDynamicMask(frame, result.T_world_camera, result.points, mask_config_);
  return tracker_.Update(result.stamp_s, ObservationsFromMask(mask_, objects_config_));
}

}  // namespace dslam
