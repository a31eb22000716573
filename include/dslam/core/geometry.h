#pragma once
// Small helpers shared by the parts: the skew-symmetric (cross-product) matrix, the rotation of a
// covariance into another frame, the whitening of a 3D residual and a rotation's angle.

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

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

/// Upper-triangular S with S^T S = C^-1 for a covariance C (S = L^T, L L^T = C^-1), so that
/// ||S e||^2 = e^T C^-1 e: the whitening of a residual e with covariance C.
inline Eigen::Matrix3d SqrtInformation(const Eigen::Matrix3d& covariance) {
  const Eigen::Matrix3d information = covariance.inverse();
  return Eigen::LLT<Eigen::Matrix3d>(information).matrixU();
}

/// [deg] Angle of the rotation `R` (the angle of its axis-angle form), in [0, 180].
inline double RotationAngleDeg(const Eigen::Matrix3d& R) {
  return Eigen::AngleAxisd(R).angle() * 180.0 / M_PI;
}

}  // namespace dslam
