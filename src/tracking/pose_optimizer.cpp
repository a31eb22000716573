#include "dslam/tracking/pose_optimizer.h"

#include <algorithm>
#include <limits>
#include <memory>

#include <ceres/ceres.h>
#include <Eigen/Cholesky>

#include "dslam/core/geometry.h"

namespace dslam {
namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

// d pi(p) / d p of the pinhole projection [px/m] at camera-frame point p.
Eigen::Matrix<double, 2, 3> ProjectionJacobian(const Eigen::Vector3d& p, double fx, double fy) {
  Eigen::Matrix<double, 2, 3> J;
  J << fx / p.z(), 0.0, -fx * p.x() / (p.z() * p.z()), 0.0, fy / p.z(),
      -fy * p.y() / (p.z() * p.z());
  return J;
}

// Writes the Jacobians of a residual r = f(q * p_world + t) with respect to the quaternion
// coefficients and t (Ceres row-major blocks; null blocks are skipped), given df/dp_camera.
template <int N>
void WritePoseJacobians(const Eigen::Matrix<double, N, 3>& d_residual_d_point,
                        const Eigen::Quaterniond& q, const Eigen::Vector3d& p_world,
                        double** jacobians) {
  if (jacobians[0] != nullptr) {
    Eigen::Map<Eigen::Matrix<double, N, 4, Eigen::RowMajor>> J_q(jacobians[0]);
    J_q = d_residual_d_point * RotatedPointByQuaternion(q, p_world);
  }
  if (jacobians[1] != nullptr) {
    Eigen::Map<Eigen::Matrix<double, N, 3, Eigen::RowMajor>> J_t(jacobians[1]);
    J_t = d_residual_d_point;
  }
}

// Paper Eq. rgbd_yik: r = C^{-1/2} (R_cw p_w + t_cw - y). Parameters: quaternion (x y z w), t.
// Analytic Jacobians (autodiff of the same expression cost most of the pose solve).
class DepthResidual : public ceres::SizedCostFunction<3, 4, 3> {
 public:
  DepthResidual(const Eigen::Vector3d& p_world, const Eigen::Vector3d& y,
                const Eigen::Matrix3d& sqrt_information)
      : p_world_(p_world), y_(y), sqrt_information_(sqrt_information) {}

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Map<const Eigen::Quaterniond> q(parameters[0]);
    const Eigen::Map<const Eigen::Vector3d> t(parameters[1]);
    Eigen::Map<Eigen::Vector3d> r(residuals);
    r = sqrt_information_ * (q * p_world_ + t - y_);
    if (jacobians != nullptr) WritePoseJacobians<3>(sqrt_information_, q, p_world_, jacobians);
    return true;
  }

  static std::unique_ptr<ceres::CostFunction> Create(const PoseObservation& o) {
    return std::make_unique<DepthResidual>(o.p_world, o.y_camera, SqrtInformation(o.covariance));
  }

 private:
  Eigen::Vector3d p_world_, y_;
  Eigen::Matrix3d sqrt_information_;
};

// Reprojection residual r = (pi(R_cw p_w + t_cw) - uv_ideal) / sigma_px, analytic Jacobians.
class PixelResidual : public ceres::SizedCostFunction<2, 4, 3> {
 public:
  PixelResidual(const Eigen::Vector3d& p_world, const Eigen::Vector2d& uv, double sigma_px,
                const PinholeCamera& camera)
      : p_world_(p_world),
        uv_(uv),
        inv_sigma_(1.0 / sigma_px),
        fx_(camera.fx()),
        fy_(camera.fy()),
        cx_(camera.cx()),
        cy_(camera.cy()) {}

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Map<const Eigen::Quaterniond> q(parameters[0]);
    const Eigen::Map<const Eigen::Vector3d> t(parameters[1]);
    const Eigen::Vector3d p = q * p_world_ + t;
    residuals[0] = (fx_ * p.x() / p.z() + cx_ - uv_.x()) * inv_sigma_;
    residuals[1] = (fy_ * p.y() / p.z() + cy_ - uv_.y()) * inv_sigma_;
    if (jacobians == nullptr) return true;
    const Eigen::Matrix<double, 2, 3> d_residual = ProjectionJacobian(p, fx_, fy_) * inv_sigma_;
    WritePoseJacobians<2>(d_residual, q, p_world_, jacobians);
    return true;
  }

  static std::unique_ptr<ceres::CostFunction> Create(const PoseObservation& o,
                                                     const PinholeCamera& camera) {
    return std::make_unique<PixelResidual>(o.p_world, o.uv_ideal, o.pixel_sigma_px, camera);
  }

 private:
  Eigen::Vector3d p_world_;
  Eigen::Vector2d uv_;
  double inv_sigma_, fx_, fy_, cx_, cy_;
};

// Whitened Jacobian rows of one observation w.r.t. [dtheta_c, dt_c] (left perturbation).
Eigen::MatrixXd WhitenedJacobian(const PoseObservation& o, const Eigen::Isometry3d& T_cw,
                                 const PinholeCamera& camera) {
  const Eigen::Vector3d p = T_cw * o.p_world;
  Eigen::Matrix<double, 3, 6> dp;
  dp << -Skew(p), Eigen::Matrix3d::Identity();
  if (o.has_depth) return SqrtInformation(o.covariance) * dp;
  return ProjectionJacobian(p, camera.fx(), camera.fy()) * dp / o.pixel_sigma_px;
}

// One optimisation round over the observations flagged in `use`; updates q and t.
ceres::Solver::Summary SolveRound(const std::vector<PoseObservation>& obs,
                                  const std::vector<bool>& use, const PinholeCamera& camera,
                                  const PoseConfig& config, Eigen::Quaterniond* q,
                                  Eigen::Vector3d* t) {
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  ceres::HuberLoss huber_depth(config.huber_delta_depth), huber_pixel(config.huber_delta_pixel);
  ceres::EigenQuaternionManifold quaternion_manifold;
  for (size_t i = 0; i < obs.size(); ++i) {
    if (!use[i]) continue;
    if (obs[i].has_depth) {
      problem.AddResidualBlock(DepthResidual::Create(obs[i]).release(), &huber_depth,
                               q->coeffs().data(), t->data());
    } else {
      problem.AddResidualBlock(PixelResidual::Create(obs[i], camera).release(), &huber_pixel,
                               q->coeffs().data(), t->data());
    }
  }
  problem.SetManifold(q->coeffs().data(), &quaternion_manifold);
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = config.max_iterations;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  return summary;
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
                        const PoseConfig& config, const std::vector<bool>* initial_inliers) {
  PoseResult result;
  result.T_camera_world = T_camera_world_guess;
  result.inliers.assign(observations.size(), true);
  if (initial_inliers && initial_inliers->size() == observations.size()) {
    result.inliers = *initial_inliers;
  }
  if (std::count(result.inliers.begin(), result.inliers.end(), true) < 3) return result;
  Eigen::Quaterniond q(T_camera_world_guess.rotation());
  Eigen::Vector3d t = T_camera_world_guess.translation();
  for (int round = 0; round < config.rounds; ++round) {
    const ceres::Solver::Summary summary =
        SolveRound(observations, result.inliers, camera, config, &q, &t);
    result.iterations += static_cast<int>(summary.iterations.size());
    result.final_cost = summary.final_cost;
    result.success = summary.IsSolutionUsable();
    if (!result.success) return result;
    q.normalize();
    result.T_camera_world = ToIsometry(q, t);
    result.num_inliers = 0;
    for (size_t i = 0; i < observations.size(); ++i) {
      const double chi2 = observations[i].has_depth ? config.chi2_depth : config.chi2_pixel;
      result.inliers[i] = SquaredError(observations[i], result.T_camera_world, camera) < chi2;
      result.num_inliers += result.inliers[i];
    }
    if (result.num_inliers < 3) {
      result.success = false;
      return result;
    }
  }
  for (size_t i = 0; i < observations.size(); ++i) {
    if (!result.inliers[i]) continue;
    const Eigen::MatrixXd J = WhitenedJacobian(observations[i], result.T_camera_world, camera);
    result.information += J.transpose() * J;
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

Eigen::Matrix<double, 6, 6> CovarianceWorldCamera(const Matrix6d& information,
                                                  const Eigen::Isometry3d& T_camera_world) {
  const Matrix6d A = PerturbationToWorldCamera(T_camera_world);
  const Matrix6d covariance = information.ldlt().solve(Matrix6d::Identity());
  return A * covariance * A.transpose();
}

}  // namespace dslam
