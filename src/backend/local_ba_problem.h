#pragma once
// The problem local bundle adjustment (local_bundle_adjustment.cpp) solves: its unknowns and
// measurements (Window) and the residual of one RGB-D measurement of a map point in a keyframe
// for Ceres. Private to the backend's sources: it includes Ceres, which the public headers keep
// out.

#include <memory>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <ceres/ceres.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/core/geometry.h"
#include "dslam/tracking/map.h"
#include "dslam/tracking/pose_optimizer.h"

namespace dslam {
namespace local_ba {

/// Paper Eq. rgbd_yik for keyframe k and point i: r = S (R_k p_i + t_k - y_ik), S^T S = C_ik^-1.
/// Parameters: quaternion of R_camera_world (x y z w), t_camera_world [m], p_world [m]. Analytic
/// Jacobians, as the motion-only BA's residuals.
class KeyFrameDepthResidual : public ceres::SizedCostFunction<3, 4, 3, 3> {
 public:
  /// `y` [m]: the measurement in the keyframe's optical frame; `sqrt_information` [1/m]: S.
  KeyFrameDepthResidual(const Eigen::Vector3d& y, const Eigen::Matrix3d& sqrt_information)
      : y_(y), sqrt_information_(sqrt_information) {}

  /// Ceres' evaluation: r [-] (whitened) and its Jacobians.
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Map<const Eigen::Quaterniond> q(parameters[0]);
    const Eigen::Map<const Eigen::Vector3d> t(parameters[1]);
    const Eigen::Map<const Eigen::Vector3d> p(parameters[2]);
    Eigen::Map<Eigen::Vector3d> r(residuals);
    r = sqrt_information_ * (q * p + t - y_);
    if (jacobians == nullptr) return true;
    if (jacobians[0] != nullptr) {
      Eigen::Map<Eigen::Matrix<double, 3, 4, Eigen::RowMajor>> J_q(jacobians[0]);
      J_q = sqrt_information_ * RotatedPointByQuaternion(q, p);
    }
    if (jacobians[1] != nullptr) {
      Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> J_t(jacobians[1]);
      J_t = sqrt_information_;
    }
    if (jacobians[2] != nullptr) {
      Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> J_p(jacobians[2]);
      J_p = sqrt_information_ * q.toRotationMatrix();
    }
    return true;
  }

  /// The residual of measurement `m` (y_camera [m], covariance [m^2]).
  static std::unique_ptr<ceres::CostFunction> Create(const PointMeasurement& m) {
    return std::make_unique<KeyFrameDepthResidual>(m.y_camera, SqrtInformation(m.covariance));
  }

 private:
  Eigen::Vector3d y_;
  Eigen::Matrix3d sqrt_information_;
};

/// A keyframe pose as Ceres' parameter blocks: world -> optical frame.
struct KeyFramePose {
  Eigen::Quaterniond q_camera_world;  ///< rotation world -> optical frame
  Eigen::Vector3d t_camera_world;     ///< [m] translation world -> optical frame
};

/// One RGB-D measurement of a window point in a window keyframe.
struct Measurement {
  int keyframe = 0;                         ///< index into the window
  PointId point = -1;                       ///< the point measured
  const PointMeasurement* value = nullptr;  ///< y [m] and C [m^2], in the keyframe
};

/// The unknowns and the measurements between them. Frozen keyframes and points (Map::Freeze: a
/// loaded map used for localisation only) enter as constants.
struct Window {
  std::vector<KeyFramePose> poses;                      ///< per window keyframe
  std::vector<bool> frozen_pose;                        ///< per window keyframe
  std::unordered_map<PointId, Eigen::Vector3d> points;  ///< [m] p_world of the points optimised
  std::unordered_set<PointId> frozen_points;            ///< those of them frozen
  std::vector<Measurement> measurements;                ///< in keyframe order
};

}  // namespace local_ba
}  // namespace dslam
