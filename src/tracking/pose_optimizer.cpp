#include "dslam/tracking/pose_optimizer.h"

#include <algorithm>
#include <limits>
#include <optional>

#include <Eigen/Cholesky>

#include "dslam/core/geometry.h"
#include "pose_solver.h"

namespace dslam {
namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

// Adds J^T J of one observation's whitened Jacobian J w.r.t. [dtheta_c, dt_c] at T_cw, for the
// perturbation the solvers use, (Exp(dtheta_c) R_cw, t_cw + dt_c): p = R_cw p_w + t_cw moves by
// -[R_cw p_w]x dtheta_c + dt_c (the translation is not rotated). `S` is the observation's C^-1/2
// (depth).
void AddInformation(const PoseObservation& o, const Eigen::Matrix3d& S,
                    const Eigen::Isometry3d& T_cw, const PinholeCamera& camera,
                    Matrix6d* information) {
  const Eigen::Vector3d p_rotated = T_cw.linear() * o.p_world;
  const Eigen::Vector3d p = p_rotated + T_cw.translation();
  Eigen::Matrix<double, 3, 6> dp;
  dp << -Skew(p_rotated), Eigen::Matrix3d::Identity();
  if (o.has_depth) {
    const Eigen::Matrix<double, 3, 6> J = S * dp;
    information->noalias() += J.transpose() * J;
    return;
  }
  const Eigen::Matrix<double, 2, 6> J =
      internal::ProjectionJacobian(p, camera.fx(), camera.fy()) * dp / o.pixel_sigma_px;
  information->noalias() += J.transpose() * J;
}

// SquaredError() with the depth residual whitened by `S` = C^-1/2 (the same value up to
// rounding, without a decomposition per call).
double WhitenedSquaredError(const PoseObservation& o, const Eigen::Matrix3d& S,
                            const Eigen::Isometry3d& T_cw, const PinholeCamera& camera) {
  if (!o.has_depth) return SquaredError(o, T_cw, camera);
  return (S * (T_cw * o.p_world - o.y_camera)).squaredNorm();
}

// Re-classifies every observation by its squared Mahalanobis error at result->T_camera_world
// (chi2_depth for 3 dof, chi2_pixel for 2 dof): inliers, num_inliers, num_observations and the
// inliers' mean error per degree of freedom.
void Classify(const std::vector<PoseObservation>& observations,
              const std::vector<Eigen::Matrix3d>& sqrt_information, const PinholeCamera& camera,
              const PoseConfig& config, PoseResult* result) {
  double chi2_sum = 0.0;
  int dof = 0;
  result->num_inliers = 0;
  for (size_t i = 0; i < observations.size(); ++i) {
    const bool depth = observations[i].has_depth;
    const double chi2 =
        WhitenedSquaredError(observations[i], sqrt_information[i], result->T_camera_world, camera);
    result->inliers[i] = chi2 < (depth ? config.chi2_depth : config.chi2_pixel);
    if (!result->inliers[i]) continue;
    ++result->num_inliers;
    chi2_sum += chi2;
    dof += depth ? 3 : 2;
  }
  result->num_observations = static_cast<int>(observations.size());
  result->inlier_chi2_per_dof = dof > 0 ? chi2_sum / dof : 0.0;
}

Eigen::Isometry3d ToIsometry(const Eigen::Quaterniond& q, const Eigen::Vector3d& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.normalized().toRotationMatrix();
  T.translation() = t;
  return T;
}

}  // namespace

Eigen::Matrix<double, 3, 4> RotatedPointByQuaternion(const Eigen::Quaterniond& q,
                                                     const Eigen::Vector3d& p) {
  const Eigen::Vector3d u = q.vec();
  Eigen::Matrix<double, 3, 4> J;
  J.leftCols<3>() =
      -2.0 * q.w() * Skew(p) +
      2.0 * (u * p.transpose() + u.dot(p) * Eigen::Matrix3d::Identity() - 2.0 * p * u.transpose());
  J.col(3) = 2.0 * u.cross(p);
  return J;
}

PoseObservation PoseObservation::WithDepth(const Eigen::Vector3d& p_world,
                                           const PointMeasurement& m) {
  PoseObservation o;
  o.p_world = p_world;
  o.has_depth = true;
  o.y_camera = m.y_camera;
  o.covariance = m.covariance;
  return o;
}

PoseObservation PoseObservation::PixelOnly(const Eigen::Vector3d& p_world,
                                           const Eigen::Vector2d& uv_ideal, double pixel_sigma_px) {
  PoseObservation o;
  o.p_world = p_world;
  o.uv_ideal = uv_ideal;
  o.pixel_sigma_px = pixel_sigma_px;
  return o;
}

double SquaredError(const PoseObservation& o, const Eigen::Isometry3d& T_camera_world,
                    const PinholeCamera& camera) {
  const Eigen::Vector3d p = T_camera_world * o.p_world;
  if (o.has_depth) {
    const Eigen::Vector3d e = p - o.y_camera;
    return e.dot(o.covariance.ldlt().solve(e));
  }
  if (p.z() <= 1e-6) return std::numeric_limits<double>::infinity();
  return ((camera.Project(p) - o.uv_ideal) / o.pixel_sigma_px).squaredNorm();
}

PoseResult EstimatePose(const std::vector<PoseObservation>& observations,
                        const Eigen::Isometry3d& T_camera_world_guess, const PinholeCamera& camera,
                        const PoseConfig& config, const std::vector<bool>* initial_inliers,
                        PoseSolver solver_kind) {
  PoseResult result;
  result.T_camera_world = T_camera_world_guess;
  result.inliers.assign(observations.size(), true);
  if (initial_inliers && initial_inliers->size() == observations.size()) {
    result.inliers = *initial_inliers;
  }
  if (std::count(result.inliers.begin(), result.inliers.end(), true) < 3) return result;
  Eigen::Quaterniond q(T_camera_world_guess.rotation());
  Eigen::Vector3d t = T_camera_world_guess.translation();
  const bool use_ceres = solver_kind == PoseSolver::kCeres;
  const std::vector<Eigen::Matrix3d> sqrt_information = internal::SqrtInformations(observations);
  std::optional<internal::PoseLevenbergMarquardt> solver;
  if (!use_ceres) solver.emplace(observations, sqrt_information, camera, config);
  for (int round = 0; round < config.rounds; ++round) {
    const internal::PoseRoundSummary summary =
        use_ceres
            ? internal::SolvePoseRoundCeres(observations, result.inliers, camera, config, &q, &t)
            : solver->Solve(result.inliers, &q, &t);
    result.iterations += summary.iterations;
    result.final_cost = summary.final_cost;
    result.success = summary.usable;
    if (!result.success) return result;
    q.normalize();
    result.T_camera_world = ToIsometry(q, t);
    Classify(observations, sqrt_information, camera, config, &result);
    if (result.num_inliers < 3) {
      result.success = false;
      return result;
    }
  }
  for (size_t i = 0; i < observations.size(); ++i) {
    if (!result.inliers[i]) continue;
    AddInformation(observations[i], sqrt_information[i], result.T_camera_world, camera,
                   &result.information);
  }
  return result;
}

Eigen::Matrix<double, 6, 6> PerturbationToWorldCamera(const Eigen::Isometry3d& T_camera_world) {
  // R_wc' = R_cw^T Exp(-dtheta_c) = Exp(-R_wc dtheta_c) R_wc;
  // p_wc' = -R_wc' (t + dt_c) = p_wc - R_wc dt_c - R_wc [t]x dtheta_c (first order).
  const Eigen::Matrix3d R_wc = T_camera_world.rotation().transpose();
  const Eigen::Vector3d t = T_camera_world.translation();
  Matrix6d A = Matrix6d::Zero();
  A.block<3, 3>(0, 0) = -R_wc * Skew(t);
  A.block<3, 3>(0, 3) = -R_wc;
  A.block<3, 3>(3, 0) = -R_wc;
  return A;
}

bool InvertibleInformation(const Matrix6d& information) {
  if (information.isZero()) return false;
  const Eigen::LDLT<Matrix6d> ldlt(information);
  return ldlt.info() == Eigen::Success && ldlt.isPositive() &&
         ldlt.vectorD().minCoeff() > 1e-12 * std::max(1.0, ldlt.vectorD().maxCoeff());
}

Eigen::Matrix<double, 6, 6> CovarianceWorldCamera(const Matrix6d& information,
                                                  const Eigen::Isometry3d& T_camera_world) {
  const Matrix6d A = PerturbationToWorldCamera(T_camera_world);
  const Matrix6d covariance = information.ldlt().solve(Matrix6d::Identity());
  return A * covariance * A.transpose();
}

}  // namespace dslam
