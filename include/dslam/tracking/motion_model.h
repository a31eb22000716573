#pragma once
// Constant-velocity motion model: predicts the next camera pose from the last two tracked ones.

#include <Eigen/Geometry>

namespace dslam {

/// Keeps the last tracked pose and the velocity between the last two, in the camera frame.
class ConstantVelocityModel {
 public:
  /// Records a tracked pose (optical frame -> world) at `stamp_s` [s].
  void Update(double stamp_s, const Eigen::Isometry3d& T_world_camera);

  /// Pose predicted for `stamp_s` [s]: the last pose moved on by the last velocity, scaled to
  /// the elapsed time. The last pose when fewer than two are known or when more than
  /// `max_gap_s` [s] passed since the last one (IsGap).
  Eigen::Isometry3d Predict(double stamp_s, double max_gap_s) const;

  /// True when a pose is known and more than `max_gap_s` [s] passed since it.
  bool IsGap(double stamp_s, double max_gap_s) const {
    return has_pose_ && stamp_s - last_stamp_s_ > max_gap_s;
  }

  /// Replaces the last pose by a refined estimate of it (e.g. after bundle adjustment); the
  /// velocity, in the camera frame, is kept.
  void CorrectLastPose(const Eigen::Isometry3d& T_world_camera) { T_world_last_ = T_world_camera; }

  /// Forgets the velocity (keeps the last pose), e.g. after tracking was lost.
  void ForgetVelocity() { has_velocity_ = false; }

  /// Forgets everything; the last pose becomes the identity (the world origin).
  void Reset() {
    has_pose_ = has_velocity_ = false;
    T_world_last_ = Eigen::Isometry3d::Identity();
  }

  bool has_pose() const { return has_pose_; }
  const Eigen::Isometry3d& last_pose() const { return T_world_last_; }

 private:
  bool has_pose_ = false, has_velocity_ = false;
  double last_stamp_s_ = 0.0;
  Eigen::Isometry3d T_world_last_ = Eigen::Isometry3d::Identity();
  Eigen::Vector3d rotation_rate_ = Eigen::Vector3d::Zero();     ///< [rad/s] axis-angle, camera
  Eigen::Vector3d translation_rate_ = Eigen::Vector3d::Zero();  ///< [m/s] in the last camera
};

}  // namespace dslam
