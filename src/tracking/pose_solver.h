#pragma once
// Internal to dslam_tracking: one optimisation round of the motion-only BA (pose_optimizer.h).
// Both solvers minimise the same cost, 1/2 sum_i rho(||r_i||^2) over the observations flagged in
// `use` (r_i whitened: depth residuals with C^-1/2, pixel residuals divided by sigma; rho the Huber
// function of PoseConfig's widths, rho(s) = s for s <= d^2, 2 d sqrt(s) - d^2 otherwise), over the
// rotation q_camera_world (perturbed on the left) and the translation t_camera_world.

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/tracking/pose_optimizer.h"

namespace dslam {
namespace internal {

/// Outcome of one round.
struct PoseRoundSummary {
  bool usable = false;      ///< the pose may be used (converged or iteration limit reached)
  double final_cost = 0.0;  ///< [-] the cost above at the returned pose
  int iterations = 0;       ///< iterations including the evaluation at the start (Ceres' count)
};

/// d pi(p) / d p of the pinhole projection [px/m] at camera-frame point p.
inline Eigen::Matrix<double, 2, 3> ProjectionJacobian(const Eigen::Vector3d& p, double fx,
                                                      double fy) {
  Eigen::Matrix<double, 2, 3> J;
  J << fx / p.z(), 0.0, -fx * p.x() / (p.z() * p.z()), 0.0, fy / p.z(),
      -fy * p.y() / (p.z() * p.z());
  return J;
}

/// C^-1/2 (SqrtInformation() of the covariance) of every observation with depth; identity for
/// pixel-only observations.
std::vector<Eigen::Matrix3d> SqrtInformations(const std::vector<PoseObservation>& observations);

/// One round solved by Ceres (Levenberg-Marquardt, DENSE_QR, EigenQuaternionManifold,
/// config.max_iterations); updates q and t.
PoseRoundSummary SolvePoseRoundCeres(const std::vector<PoseObservation>& observations,
                                     const std::vector<bool>& use, const PinholeCamera& camera,
                                     const PoseConfig& config, Eigen::Quaterniond* q,
                                     Eigen::Vector3d* t);

/// Hand-written Levenberg-Marquardt over the 6 pose parameters: the Huber loss as iteratively
/// reweighted least squares (weight rho'(s)), the 6x6 normal equations accumulated directly and
/// solved by LDLT. Step control and stopping rules are those of Ceres' trust-region minimiser with
/// its default options (initial radius 1e4, Jacobi scaling from the first Jacobian, step accepted
/// when the relative decrease exceeds 1e-3; function tolerance 1e-6, gradient tolerance 1e-10,
/// parameter tolerance 1e-8; at most config.max_iterations steps) and the same tangent space (half
/// rotation angle, as Ceres' EigenQuaternionManifold), so both take the same steps up to rounding.
class PoseLevenbergMarquardt {
 public:
  /// Keeps references to the arguments (they must outlive the solver); `sqrt_information` is
  /// SqrtInformations(observations).
  PoseLevenbergMarquardt(const std::vector<PoseObservation>& observations,
                         const std::vector<Eigen::Matrix3d>& sqrt_information,
                         const PinholeCamera& camera, const PoseConfig& config);

  /// One round over the observations flagged in `use`, from and into q and t.
  PoseRoundSummary Solve(const std::vector<bool>& use, Eigen::Quaterniond* q,
                         Eigen::Vector3d* t) const;

 private:
  using Matrix6d = Eigen::Matrix<double, 6, 6>;
  using Vector6d = Eigen::Matrix<double, 6, 1>;

  /// Cost, Gauss-Newton matrix and gradient in the tangent space [delta (half angle), dt].
  struct Linearization {
    double cost = 0.0;
    Matrix6d H = Matrix6d::Zero();
    Vector6d g = Vector6d::Zero();
  };

  /// Evaluates the cost and its derivatives at (q, t); cost = +inf when a residual is not finite.
  void Linearize(const std::vector<bool>& use, const Eigen::Quaterniond& q,
                 const Eigen::Vector3d& t, Linearization* out) const;

  /// Levenberg-Marquardt step in the tangent space for trust-region `radius`, with the Jacobi
  /// column `scale` fixed at the start of the round.
  static Vector6d DampedStep(const Linearization& at, const Vector6d& scale, double radius);

  const std::vector<PoseObservation>& observations_;
  const std::vector<Eigen::Matrix3d>& sqrt_information_;
  const PinholeCamera& camera_;
  const PoseConfig& config_;
};

}  // namespace internal
}  // namespace dslam
