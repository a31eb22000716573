#include "dslam/eval/groundtruth_correction.h"

#include <Eigen/SVD>

namespace dslam {

Eigen::Matrix4d BonnAxisChange() {
  Eigen::Matrix4d t_ros;
  t_ros << -1, 0, 0, 0,  //
      0, 0, 1, 0,        //
      0, 1, 0, 0,        //
      0, 0, 0, 1;
  return t_ros;
}

Eigen::Matrix4d BonnMarkerToCameraRaw() {
  Eigen::Matrix4d t_m;
  t_m << 1.0157, 0.1828, -0.2389, 0.0113,  //
      0.0009, -0.8431, -0.6413, -0.0098,   //
      -0.3009, 0.6147, -0.8085, 0.0111,    //
      0, 0, 0, 1;
  return t_m;
}

Eigen::Matrix3d NearestRotation(const Eigen::Matrix3d& m) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d& u = svd.matrixU();
  const Eigen::Matrix3d& v = svd.matrixV();
  Eigen::Vector3d diagonal(1.0, 1.0, (u * v.transpose()).determinant() < 0.0 ? -1.0 : 1.0);
  return u * diagonal.asDiagonal() * v.transpose();
}

Eigen::Isometry3d BonnMarkerToCamera() {
  const Eigen::Matrix4d raw = BonnMarkerToCameraRaw();
  Eigen::Isometry3d t_m = Eigen::Isometry3d::Identity();
  t_m.linear() = NearestRotation(raw.topLeftCorner<3, 3>());
  t_m.translation() = raw.topRightCorner<3, 1>();
  return t_m;
}

Eigen::Isometry3d BonnCameraPose(const Eigen::Isometry3d& T_world_marker) {
  // Constants of the correction, computed once (T_m needs an SVD).
  static const Eigen::Matrix4d t_ros = BonnAxisChange();
  static const Eigen::Isometry3d T_marker_camera = BonnMarkerToCamera();
  // T_ros is its own inverse: this is a change of axes on both sides, a proper rigid transform.
  const Eigen::Matrix4d conjugated = t_ros * T_world_marker.matrix() * t_ros;
  Eigen::Isometry3d T_axes_marker = Eigen::Isometry3d::Identity();
  T_axes_marker.linear() = conjugated.topLeftCorner<3, 3>();
  T_axes_marker.translation() = conjugated.topRightCorner<3, 1>();
  return T_axes_marker * T_marker_camera;
}

Trajectory ApplyGroundTruthCorrection(const Trajectory& groundtruth,
                                      GroundTruthCorrection correction) {
  Trajectory corrected = groundtruth;
  if (correction == GroundTruthCorrection::kNone) return corrected;
  for (StampedPose& pose : corrected) pose.T_world_camera = BonnCameraPose(pose.T_world_camera);
  return corrected;
}

}  // namespace dslam
