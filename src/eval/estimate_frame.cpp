// The frame of dslam_run_dataset's outputs in the ground truth's world (estimate_frame.h).
#include "dslam/eval/estimate_frame.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dslam {
namespace {

const StampedPose& NearestPose(const Trajectory& poses, double stamp_s, double max_dt_s) {
  const StampedPose* best = nullptr;
  for (const StampedPose& pose : poses) {
    if (!best || std::abs(pose.stamp_s - stamp_s) < std::abs(best->stamp_s - stamp_s)) {
      best = &pose;
    }
  }
  if (!best || std::abs(best->stamp_s - stamp_s) > max_dt_s) {
    throw std::runtime_error("no ground-truth pose within " + std::to_string(max_dt_s) +
                             " s of stamp " + std::to_string(stamp_s));
  }
  return *best;
}

}  // namespace

Eigen::Isometry3d EstimateFrameInWorld(const Trajectory& groundtruth, double first_frame_stamp_s,
                                       const Trajectory& estimated, double max_dt_s) {
  if (estimated.empty()) {
    return NearestPose(groundtruth, first_frame_stamp_s, max_dt_s).T_world_camera;
  }
  const StampedPose* first = &estimated.front();
  for (const StampedPose& pose : estimated) {
    if (pose.stamp_s < first->stamp_s) first = &pose;
  }
  return NearestPose(groundtruth, first->stamp_s, max_dt_s).T_world_camera *
         first->T_world_camera.inverse();
}

}  // namespace dslam
