#include "dslam/ros/odom_integrator.h"

namespace dslam {
namespace ros_layer {

void OdomIntegrator::Add(const FrameResult& result) {
  if (!result.has_pose) return;
  const Eigen::Isometry3d& T_map_camera = result.T_world_camera;
  if (!has_pose_) {
    T_odom_camera_ = T_map_camera;  // odom starts where the map is: T_map_odom = identity
  } else if (result.has_previous_pose &&
             result.T_world_previous_camera.matrix() == T_map_last_camera_.matrix()) {
    // No correction since the last pose: T_map_odom stays as it is. Computed from the tracked
    // pose (not integrated), so round-off does not accumulate; exact with the identity.
    T_odom_camera_ = T_map_odom_.inverse() * T_map_camera;
  } else {
    if (result.has_previous_pose) {  // corrected between the frames: odom takes the motion only
      T_odom_camera_ = T_odom_camera_ * (result.T_world_previous_camera.inverse() * T_map_camera);
    }  // else a jump: odom stays where it was
    T_map_odom_ = T_map_camera * T_odom_camera_.inverse();
  }
  T_map_last_camera_ = T_map_camera;
  has_pose_ = true;
}

}  // namespace ros_layer
}  // namespace dslam
