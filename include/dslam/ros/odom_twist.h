#pragma once
// The twist of nav_msgs/Odometry: the base frame's velocity between the last two tracked frames
// and its covariance from the pose solver's information of both. No ROS headers: test_ros tests
// it without a node.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/tracking/frame_result.h"

namespace dslam {
namespace ros_layer {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// [6x6] Maps the pose solver's perturbation [dtheta, dt] of T_camera_world
/// (PoseResult::information's order: rotation about the camera axes on the left, translation
/// added) to the base frame's own perturbation [rho (3, m), phi (3, rad)]: T_world_base <-
/// T_world_base * (Exp(phi), rho), both in the base frame's axes, for the camera mount
/// T_base_camera [m].
Matrix6d BasePerturbationFromSolver(const Eigen::Isometry3d& T_camera_world,
                                    const Eigen::Isometry3d& T_base_camera);

/// The base frame's velocity for `odom` (REP 105: in the child frame, the base): the motion
/// between the last two frames with a pose tracked from one to the next, divided by their time
/// apart. Covariance: the two poses' covariances in the base frame summed (their errors taken
/// as independent, which overstates it: both rest on many of the same map points) over dt^2.
class OdomTwist {
 public:
  /// Takes one frame's result after OdomIntegrator took it, with T_odom_camera its odom pose
  /// then (optical frames) and the camera mount T_base_camera [m]. Without a pose, or with a pose
  /// not tracked from the previous frame (first frame, after lost frames, relocalised), or with a
  /// stamp not after the previous one, the twist is unknown.
  void Add(const FrameResult& result, const Eigen::Isometry3d& T_odom_camera,
           const Eigen::Isometry3d& T_base_camera);
  /// Forgets the previous frame: the twist is unknown until two frames tracked in a row.
  void Restart() { *this = OdomTwist(); }

  /// Whether velocity() is measured; else it is zero and the covariance `unknown_variance`.
  bool known() const { return known_; }
  /// [m/s, rad/s] [vx vy vz wx wy wz] of the base frame in its own axes (those of the earlier
  /// frame of the two; ROS order).
  const Vector6d& velocity() const { return velocity_; }
  /// [(m/s)^2, (rad/s)^2] Row-major covariance of velocity(), ROS order; unknown_variance on the
  /// diagonal when unknown or when a pose's information is not positive definite.
  const Matrix6d& covariance() const { return covariance_; }

  static constexpr double kUnknownVariance = 1e6;

 private:
  /// The base-frame covariance [rho, phi] of the last frame's pose; false when unknown.
  bool PoseCovariance(const FrameResult& result, const Eigen::Isometry3d& T_base_camera,
                      Matrix6d* covariance) const;

  bool has_previous_ = false;       ///< the previous frame had a pose
  double previous_stamp_s_ = 0.0;   ///< [s]
  Eigen::Isometry3d T_odom_previous_base_ = Eigen::Isometry3d::Identity();
  bool previous_covariance_known_ = false;
  Matrix6d previous_covariance_ = Matrix6d::Zero();  ///< [rho, phi] in the base frame
  bool known_ = false;
  Vector6d velocity_ = Vector6d::Zero();
  Matrix6d covariance_ = kUnknownVariance * Matrix6d::Identity();
};

}  // namespace ros_layer
}  // namespace dslam
