#include "dslam/tracking/motion_model.h"

#include <algorithm>

namespace dslam {

void ConstantVelocityModel::Update(double stamp_s, const Eigen::Isometry3d& T_world_camera) {
  const double dt = stamp_s - last_stamp_s_;
  if (has_pose_ && dt > 1e-6) {
    const Eigen::Isometry3d T_last_current = T_world_last_.inverse() * T_world_camera;
    const Eigen::AngleAxisd rotation(T_last_current.rotation());
    rotation_rate_ = rotation.axis() * rotation.angle() / dt;
    translation_rate_ = T_last_current.translation() / dt;
    has_velocity_ = true;
  }
  T_world_last_ = T_world_camera;
  last_stamp_s_ = stamp_s;
  has_pose_ = true;
}

Eigen::Isometry3d ConstantVelocityModel::Predict(double stamp_s, double max_gap_s) const {
  if (!has_velocity_ || IsGap(stamp_s, max_gap_s)) return T_world_last_;
  const double dt = std::max(stamp_s - last_stamp_s_, 0.0);
  Eigen::Isometry3d T_last_next = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d rotation = rotation_rate_ * dt;
  if (rotation.norm() > 1e-12) {
    T_last_next.linear() = Eigen::AngleAxisd(rotation.norm(), rotation.normalized()).matrix();
  }
  T_last_next.translation() = translation_rate_ * dt;
  return T_world_last_ * T_last_next;
}

}  // namespace dslam
