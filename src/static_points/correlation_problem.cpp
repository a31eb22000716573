#include "dslam/static_points/correlation_problem.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include "correlation_measurements.h"

namespace dslam {
namespace {

using internal::CorrelationMeasurement;

using Solver = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower>;

// Lower triangle of the normal equations of J_p + prior (in increments from the initial points)
// and its right-hand side. Every edge emits its block, even when all its measurements are culled,
// so the sparsity pattern stays the same across rounds.
Eigen::SparseMatrix<double> NormalEquations(const std::vector<Eigen::Vector3d>& initial,
                                            const std::vector<GraphEdge>& edges,
                                            const std::vector<CorrelationMeasurement>& ms,
                                            double prior_information, Eigen::VectorXd* rhs) {
  const int n = static_cast<int>(initial.size());
  std::vector<Eigen::Matrix3d> edge_block(edges.size(), Eigen::Matrix3d::Zero());
  std::vector<Eigen::Matrix3d> diagonal(n, prior_information * Eigen::Matrix3d::Identity());
  rhs->setZero(3 * n);
  for (const CorrelationMeasurement& m : ms) {
    if (!m.active) continue;
    const GraphEdge& e = edges[m.edge];
    const Eigen::Matrix3d rt_w = m.R_camera_world.transpose() * m.information;
    const Eigen::Matrix3d a = rt_w * m.R_camera_world;
    const Eigen::Vector3d b = rt_w * (m.z - m.R_camera_world * (initial[e.i] - initial[e.j]));
    edge_block[m.edge] += a;
    diagonal[e.i] += a;
    diagonal[e.j] += a;
    rhs->segment<3>(3 * e.i) += b;
    rhs->segment<3>(3 * e.j) -= b;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(6 * n + 9 * edges.size());
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      for (int r = c; r < 3; ++r) triplets.emplace_back(3 * i + r, 3 * i + c, diagonal[i](r, c));
    }
  }
  for (size_t k = 0; k < edges.size(); ++k) {  // block (j, i), j > i: below the diagonal
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        triplets.emplace_back(3 * edges[k].j + r, 3 * edges[k].i + c, -edge_block[k](r, c));
      }
    }
  }
  Eigen::SparseMatrix<double> h(3 * n, 3 * n);
  h.setFromTriplets(triplets.begin(), triplets.end());
  return h;
}

// One linear least-squares solve; the solver's symbolic analysis is done on the first call.
std::vector<Eigen::Vector3d> SolvePoints(const std::vector<Eigen::Vector3d>& initial,
                                         const std::vector<GraphEdge>& edges,
                                         const std::vector<CorrelationMeasurement>& measurements,
                                         double prior_information, bool analyze, Solver* solver) {
  Eigen::VectorXd rhs;
  const Eigen::SparseMatrix<double> h =
      NormalEquations(initial, edges, measurements, prior_information, &rhs);
  if (analyze) solver->analyzePattern(h);
  solver->factorize(h);
  if (solver->info() != Eigen::Success)
    throw std::runtime_error("SolvePoints: factorization failed");
  const Eigen::VectorXd delta = solver->solve(rhs);
  std::vector<Eigen::Vector3d> points(initial);
  for (size_t i = 0; i < points.size(); ++i) points[i] += delta.segment<3>(3 * i);
  return points;
}

double Chi2(const CorrelationMeasurement& m, const GraphEdge& e,
            const std::vector<Eigen::Vector3d>& points) {
  const Eigen::Vector3d err = m.z - m.R_camera_world * (points[e.i] - points[e.j]);
  return err.dot(m.information * err);
}

void Summarise(const std::vector<CorrelationMeasurement>& measurements, double min_fraction,
               CullingResult* result) {
  const size_t num_edges = result->edge_kept.size();
  result->edge_measurements.assign(num_edges, 0);
  result->edge_inliers.assign(num_edges, 0);
  result->measurements = static_cast<int>(measurements.size());
  for (const CorrelationMeasurement& m : measurements) {
    ++result->edge_measurements[m.edge];
    if (m.active) ++result->edge_inliers[m.edge];
    if (!m.active) ++result->culled_measurements;
  }
  for (size_t e = 0; e < num_edges; ++e) {
    const int total = result->edge_measurements[e];
    const int inliers = result->edge_inliers[e];
    result->edge_kept[e] = total == 0 || (inliers > 0 && inliers >= min_fraction * total);
  }
}

}  // namespace

CullingResult CullInconsistentEdges(const CorrelationInput& input,
                                    const std::vector<GraphEdge>& edges,
                                    const CullingOptions& options) {
  std::vector<CorrelationMeasurement> measurements = internal::BuildMeasurements(input, edges);
  const double prior_information = 1.0 / (options.prior_sigma_m * options.prior_sigma_m);
  CullingResult result;
  result.edge_kept.assign(edges.size(), true);
  result.points_world = input.points_world;
  Solver solver;
  for (int round = 0; round < options.max_rounds; ++round) {
    result.points_world = SolvePoints(input.points_world, edges, measurements, prior_information,
                                      round == 0, &solver);
    ++result.rounds;
    bool changed = false;
    for (CorrelationMeasurement& m : measurements) {
      m.chi2 = Chi2(m, edges[m.edge], result.points_world);
      if (m.active && m.chi2 > options.chi2_threshold) {
        m.active = false;  // one-way: never re-admitted
        changed = true;
      }
    }
    if (!changed) break;
  }
  result.edge_max_chi2.assign(edges.size(), 0.0);
  for (const CorrelationMeasurement& m : measurements) {
    result.edge_max_chi2[m.edge] = std::max(result.edge_max_chi2[m.edge], m.chi2);
  }
  Summarise(measurements, options.min_inlier_fraction, &result);
  return result;
}

}  // namespace dslam
