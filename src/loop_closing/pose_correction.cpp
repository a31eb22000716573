#include "dslam/loop_closing/pose_correction.h"

#include <stdexcept>
#include <string>

#include "dslam/core/geometry.h"

namespace dslam {

Eigen::Isometry3d KeyFrameCorrection(const Eigen::Isometry3d& T_world_keyframe,
                                     const Eigen::Isometry3d& T_world_keyframe_corrected) {
  return T_world_keyframe_corrected * T_world_keyframe.inverse();
}

Eigen::Vector3d CorrectPoint(const Eigen::Vector3d& p_world,
                             const Eigen::Isometry3d& T_world_keyframe,
                             const Eigen::Isometry3d& T_world_keyframe_corrected) {
  return KeyFrameCorrection(T_world_keyframe, T_world_keyframe_corrected) * p_world;
}

Eigen::Matrix3d CorrectPointCovariance(const Eigen::Matrix3d& cov_world,
                                       const Eigen::Isometry3d& T_world_keyframe,
                                       const Eigen::Isometry3d& T_world_keyframe_corrected) {
  const Eigen::Isometry3d T_corrected_uncorrected =
      KeyFrameCorrection(T_world_keyframe, T_world_keyframe_corrected);
  return RotatedCovariance(T_corrected_uncorrected.rotation(), cov_world);
}

Eigen::Isometry3d CorrectPose(const Eigen::Isometry3d& T_world_camera,
                              const Eigen::Isometry3d& T_world_keyframe,
                              const Eigen::Isometry3d& T_world_keyframe_corrected) {
  return KeyFrameCorrection(T_world_keyframe, T_world_keyframe_corrected) * T_world_camera;
}

Eigen::Isometry3d CorrectFramePose(const Eigen::Isometry3d& T_world_camera,
                                   int reference_keyframe_id, const PoseGraph& graph,
                                   const PoseGraphResult& result) {
  const PoseGraphNode& node = FindPoseGraphNode(graph, reference_keyframe_id);
  const auto corrected = result.T_world_camera.find(reference_keyframe_id);
  if (corrected == result.T_world_camera.end()) {
    throw std::invalid_argument("pose graph: keyframe " + std::to_string(reference_keyframe_id) +
                                " has no corrected pose in the result");
  }
  return CorrectPose(T_world_camera, node.T_world_camera, corrected->second);
}

}  // namespace dslam
