#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>

#include "dslam/core/geometry.h"
#include "pose_solver.h"

namespace dslam {
namespace internal {
namespace {

// Ceres' default Solver::Options of the trust-region minimiser and its LM strategy.
constexpr double kInitialRadius = 1e4;
constexpr double kMaxRadius = 1e16;
constexpr double kMinRadius = 1e-32;
constexpr double kMinDiagonal = 1e-6;
constexpr double kMaxDiagonal = 1e32;
constexpr double kMinRelativeDecrease = 1e-3;
constexpr double kFunctionTolerance = 1e-6;
constexpr double kGradientTolerance = 1e-10;
constexpr double kParameterTolerance = 1e-8;
constexpr int kMaxConsecutiveInvalidSteps = 5;

// Huber rho(s) and rho'(s) of a squared whitened norm s with width `delta`.
void Huber(double s, double delta, double* rho, double* weight) {
  if (s <= delta * delta) {
    *rho = s;
    *weight = 1.0;
    return;
  }
  const double r = std::sqrt(s);
  *rho = 2.0 * delta * r - delta * delta;
  *weight = delta / r;
}

// Exp(delta) * q with the half-angle tangent of Ceres' EigenQuaternionManifold.
Eigen::Quaterniond QuaternionPlus(const Eigen::Quaterniond& q, const Eigen::Vector3d& delta) {
  const double norm = delta.norm();
  if (norm == 0.0) return q;
  const Eigen::Vector3d v = std::sin(norm) / norm * delta;
  return Eigen::Quaterniond(std::cos(norm), v.x(), v.y(), v.z()) * q;
}

// Ambient-space distance between x = (q coefficients, t) and Plus(x, step): the 2-norm, or the
// max norm when `max_norm` is true.
double AmbientStepNorm(const Eigen::Quaterniond& q, const Eigen::Matrix<double, 6, 1>& step,
                       bool max_norm = false) {
  Eigen::Matrix<double, 7, 1> d;
  d << q.coeffs() - QuaternionPlus(q, step.head<3>()).coeffs(), step.tail<3>();
  return max_norm ? d.lpNorm<Eigen::Infinity>() : d.norm();
}

// Ceres' gradient test: max |x - Plus(x, -gradient)| <= gradient tolerance.
bool GradientConverged(const Eigen::Quaterniond& q, const Eigen::Matrix<double, 6, 1>& g) {
  return AmbientStepNorm(q, -g, true) <= kGradientTolerance;
}

}  // namespace

std::vector<Eigen::Matrix3d> SqrtInformations(const std::vector<PoseObservation>& observations) {
  std::vector<Eigen::Matrix3d> sqrt_information(observations.size(), Eigen::Matrix3d::Identity());
  for (size_t i = 0; i < observations.size(); ++i) {
    if (observations[i].has_depth)
      sqrt_information[i] = SqrtInformation(observations[i].covariance);
  }
  return sqrt_information;
}

PoseLevenbergMarquardt::PoseLevenbergMarquardt(const std::vector<PoseObservation>& observations,
                                               const std::vector<Eigen::Matrix3d>& sqrt_information,
                                               const PinholeCamera& camera,
                                               const PoseConfig& config)
    : observations_(observations),
      sqrt_information_(sqrt_information),
      camera_(camera),
      config_(config) {}

void PoseLevenbergMarquardt::Linearize(const std::vector<bool>& use, const Eigen::Quaterniond& q,
                                       const Eigen::Vector3d& t, Linearization* out) const {
  const Eigen::Matrix3d R = q.toRotationMatrix();
  const double fx = camera_.fx(), fy = camera_.fy(), cx = camera_.cx(), cy = camera_.cy();
  double sum_rho = 0.0, rho = 0.0, w = 0.0;
  Matrix6d H = Matrix6d::Zero();
  Vector6d g = Vector6d::Zero();
  for (size_t i = 0; i < observations_.size(); ++i) {
    if (!use[i]) continue;
    const PoseObservation& o = observations_[i];
    const Eigen::Vector3d Rp = R * o.p_world;
    const Eigen::Vector3d p = Rp + t;
    // d p / d delta = -2 [R p_w]x (half-angle tangent), d p / d t = I.
    const Eigen::Matrix3d dp_ddelta = -2.0 * Skew(Rp);
    if (o.has_depth) {
      const Eigen::Matrix3d& S = sqrt_information_[i];
      const Eigen::Vector3d r = S * (p - o.y_camera);
      Huber(r.squaredNorm(), config_.huber_delta_depth, &rho, &w);
      Eigen::Matrix<double, 3, 6> J;
      J << S * dp_ddelta, S;
      H.noalias() += w * J.transpose() * J;
      g.noalias() += w * J.transpose() * r;
    } else {
      const double inv_sigma = 1.0 / o.pixel_sigma_px;
      const Eigen::Vector2d r((fx * p.x() / p.z() + cx - o.uv_ideal.x()) * inv_sigma,
                              (fy * p.y() / p.z() + cy - o.uv_ideal.y()) * inv_sigma);
      Huber(r.squaredNorm(), config_.huber_delta_pixel, &rho, &w);
      const Eigen::Matrix<double, 2, 3> dr_dp = ProjectionJacobian(p, fx, fy) * inv_sigma;
      Eigen::Matrix<double, 2, 6> J;
      J << dr_dp * dp_ddelta, dr_dp;
      H.noalias() += w * J.transpose() * J;
      g.noalias() += w * J.transpose() * r;
    }
    sum_rho += rho;
  }
  out->cost = std::isfinite(sum_rho) ? 0.5 * sum_rho : std::numeric_limits<double>::infinity();
  out->H = H;
  out->g = g;
}

PoseLevenbergMarquardt::Vector6d PoseLevenbergMarquardt::DampedStep(const Linearization& at,
                                                                    const Vector6d& scale,
                                                                    double radius) {
  // Ceres' LM strategy on the Jacobi-scaled system: (S H S + D / radius) y = -S g with D the
  // clamped diagonal of S H S; the step is S y.
  Matrix6d A = scale.asDiagonal() * at.H * scale.asDiagonal();
  const Vector6d diagonal = A.diagonal().cwiseMax(kMinDiagonal).cwiseMin(kMaxDiagonal);
  A.diagonal() += diagonal / radius;
  return scale.cwiseProduct(A.ldlt().solve(-scale.cwiseProduct(at.g)));
}

PoseRoundSummary PoseLevenbergMarquardt::Solve(const std::vector<bool>& use, Eigen::Quaterniond* q,
                                               Eigen::Vector3d* t) const {
  PoseRoundSummary summary;
  summary.iterations = 1;
  Linearization current, candidate;
  Linearize(use, *q, *t, &current);
  if (!std::isfinite(current.cost)) return summary;
  // Jacobi scaling of the columns, fixed at the first Jacobian; scale-invariant except for the
  // clamping of the damping diagonal.
  const Vector6d scale = (1.0 + current.H.diagonal().array().sqrt()).inverse().matrix();
  double radius = kInitialRadius, decrease_factor = 2.0;
  // Ceres skips the parameter test until the first accepted step.
  double x_norm = -1.0;
  int invalid_steps = 0;
  bool converged = GradientConverged(*q, current.g);
  // summary.iterations counts as Ceres' Summary::iterations: the start and every completed
  // iteration; an iteration that ends in a tolerance test is not counted.
  for (int iteration = 1; iteration <= config_.max_iterations && !converged; ++iteration) {
    const Vector6d step = DampedStep(current, scale, radius);
    const double model_cost_change = -(step.dot(current.g) + 0.5 * step.dot(current.H * step));
    if (!step.allFinite() || !(model_cost_change > 0.0)) {
      if (++invalid_steps >= kMaxConsecutiveInvalidSteps) return summary;  // not usable
      ++summary.iterations;
      radius /= decrease_factor;
      decrease_factor *= 2.0;
      continue;
    }
    invalid_steps = 0;
    const Eigen::Quaterniond q_candidate = QuaternionPlus(*q, step.head<3>());
    const Eigen::Vector3d t_candidate = *t + step.tail<3>();
    Linearize(use, q_candidate, t_candidate, &candidate);
    if (AmbientStepNorm(*q, step) <= kParameterTolerance * (x_norm + kParameterTolerance)) break;
    const double cost_change = current.cost - candidate.cost;
    if (std::abs(cost_change) <= kFunctionTolerance * current.cost) break;
    const double relative_decrease = cost_change / model_cost_change;
    ++summary.iterations;
    if (relative_decrease > kMinRelativeDecrease) {
      *q = q_candidate;
      *t = t_candidate;
      std::swap(current, candidate);
      x_norm = std::sqrt(q->coeffs().squaredNorm() + t->squaredNorm());
      const double c = 2.0 * relative_decrease - 1.0;
      radius = std::min(kMaxRadius, radius / std::max(1.0 / 3.0, 1.0 - c * c * c));
      decrease_factor = 2.0;
      converged = GradientConverged(*q, current.g);
    } else {
      radius /= decrease_factor;
      decrease_factor *= 2.0;
      converged = radius <= kMinRadius;
    }
  }
  summary.usable = true;
  summary.final_cost = current.cost;
  return summary;
}

}  // namespace internal
}  // namespace dslam
