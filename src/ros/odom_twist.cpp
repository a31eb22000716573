#include "dslam/ros/odom_twist.h"

#include <Eigen/Cholesky>

#include "dslam/core/geometry.h"
#include "dslam/tracking/pose_optimizer.h"

namespace dslam {
namespace ros_layer {
namespace {

/// [6x6] The adjoint of T = (R, t) for perturbations [rho; phi]: a perturbation in T's child
/// frame, T * (Exp(phi), rho), is (Exp(phi'), rho') * T with [rho'; phi'] = [R rho + [t]x R phi;
/// R phi] in T's parent frame (to first order).
Matrix6d Adjoint(const Eigen::Isometry3d& T) {
  const Eigen::Matrix3d R = T.rotation();
  Matrix6d adjoint = Matrix6d::Zero();
  adjoint.block<3, 3>(0, 0) = R;
  adjoint.block<3, 3>(0, 3) = Skew(T.translation()) * R;
  adjoint.block<3, 3>(3, 3) = R;
  return adjoint;
}

}  // namespace

Matrix6d BasePerturbationFromSolver(const Eigen::Isometry3d& T_camera_world,
                                    const Eigen::Isometry3d& T_base_camera) {
  // T_camera_world <- (Exp(dtheta) R, t + dt) is T_world_camera * (Exp(-dtheta), rho) with
  // rho = -dt - [t]x dtheta in the camera's axes (to first order).
  Matrix6d camera = Matrix6d::Zero();
  camera.block<3, 3>(0, 0) = -Skew(T_camera_world.translation());
  camera.block<3, 3>(0, 3) = -Eigen::Matrix3d::Identity();
  camera.block<3, 3>(3, 0) = -Eigen::Matrix3d::Identity();
  // T_world_base = T_world_camera * T_camera_base: the camera's perturbation moves the base by
  // the adjoint of T_base_camera.
  return Adjoint(T_base_camera) * camera;
}

bool OdomTwist::PoseCovariance(const FrameResult& result, const Eigen::Isometry3d& T_base_camera,
                               Matrix6d* covariance) const {
  if (!InvertibleInformation(result.information)) return false;
  const Matrix6d J = BasePerturbationFromSolver(result.T_world_camera.inverse(), T_base_camera);
  *covariance = J * result.information.ldlt().solve(Matrix6d::Identity()) * J.transpose();
  return true;
}

void OdomTwist::Add(const FrameResult& result, const Eigen::Isometry3d& T_odom_camera,
                    const Eigen::Isometry3d& T_base_camera) {
  known_ = false;
  velocity_.setZero();
  covariance_ = kUnknownVariance * Matrix6d::Identity();
  if (!result.has_pose) {
    has_previous_ = false;
    return;
  }
  const Eigen::Isometry3d T_odom_base = T_base_camera * T_odom_camera * T_base_camera.inverse();
  Matrix6d pose_covariance;
  const bool covariance_known = PoseCovariance(result, T_base_camera, &pose_covariance);
  const double dt_s = result.stamp_s - previous_stamp_s_;
  if (has_previous_ && result.has_previous_pose && dt_s > 0.0) {
    const Eigen::Isometry3d T_previous_current = T_odom_previous_base_.inverse() * T_odom_base;
    const Eigen::AngleAxisd rotation(T_previous_current.rotation());
    velocity_.head<3>() = T_previous_current.translation() / dt_s;
    velocity_.tail<3>() = rotation.angle() * rotation.axis() / dt_s;
    known_ = true;
    if (covariance_known && previous_covariance_known_) {
      // T_previous_current's perturbation in the earlier frame's axes: -eps_previous +
      // Adjoint(T_previous_current) eps_current.
      const Matrix6d A = Adjoint(T_previous_current);
      covariance_ =
          (previous_covariance_ + A * pose_covariance * A.transpose()) / (dt_s * dt_s);
    }
  }
  has_previous_ = true;
  previous_stamp_s_ = result.stamp_s;
  T_odom_previous_base_ = T_odom_base;
  previous_covariance_known_ = covariance_known;
  previous_covariance_ = pose_covariance;
}

}  // namespace ros_layer
}  // namespace dslam
