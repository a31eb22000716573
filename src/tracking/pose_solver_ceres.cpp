#include <memory>

#include <ceres/ceres.h>

#include "dslam/core/geometry.h"
#include "dslam/tracking/pose_optimizer.h"
#include "pose_solver.h"

namespace dslam {
namespace internal {
namespace {

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

}  // namespace

PoseRoundSummary SolvePoseRoundCeres(const std::vector<PoseObservation>& obs,
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
  PoseRoundSummary round;
  round.usable = summary.IsSolutionUsable();
  round.final_cost = summary.final_cost;
  round.iterations = static_cast<int>(summary.iterations.size());
  return round;
}

}  // namespace internal
}  // namespace dslam
