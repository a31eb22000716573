#include "dslam/backend/refined_trajectory.h"

namespace dslam {

void RefinedTrajectory::AddFrame(double stamp_s, const Eigen::Isometry3d& T_world_camera,
                                 const Map& map) {
  if (map.keyframes().empty()) return;
  const KeyFrame& reference = map.keyframes().back();
  T_world_keyframe_[reference.id] = reference.T_world_camera;
  frames_.push_back({stamp_s, reference.id, reference.T_world_camera.inverse() * T_world_camera});
}

void RefinedTrajectory::UpdateKeyFrames(const Map& map) {
  for (const KeyFrame& keyframe : map.keyframes()) {
    T_world_keyframe_[keyframe.id] = keyframe.T_world_camera;
  }
  for (const auto& [id, keyframe] : map.archived_keyframes()) {
    T_world_keyframe_[id] = keyframe.T_world_camera;
  }
}

Trajectory RefinedTrajectory::Poses() const {
  Trajectory poses;
  poses.reserve(frames_.size());
  for (const Frame& frame : frames_) {
    poses.push_back(
        {frame.stamp_s, T_world_keyframe_.at(frame.keyframe_id) * frame.T_keyframe_camera});
  }
  return poses;
}

}  // namespace dslam
