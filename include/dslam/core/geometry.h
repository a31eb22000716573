#pragma once
// Small rotation helpers shared by the parts: the skew-symmetric (cross-product) matrix and the
// rotation of a covariance into another frame.

#include <Eigen/Core>

namespace dslam {

/// [v]_x: Skew(v) * w == v.cross(w).
inline Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

/// R C R^T: covariance `C` of a vector in frame b expressed in frame a, for R = R_a_b (units of C
/// unchanged). Evaluated as (R C) R^T.
inline Eigen::Matrix3d RotatedCovariance(const Eigen::Matrix3d& R, const Eigen::Matrix3d& C) {
  return R * C * R.transpose();
}

}  // namespace dslam
