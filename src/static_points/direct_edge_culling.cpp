// DirectEdgeTest and ChiSquareQuantile (declared in correlation_problem.h).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

#include "correlation_measurements.h"
#include "dslam/static_points/correlation_problem.h"

namespace dslam {
namespace {

// Standard normal quantile by bisection on the CDF 0.5 erfc(-x / sqrt 2).
double NormalQuantile(double probability) {
  double lo = -10.0, hi = 10.0;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    const double cdf = 0.5 * std::erfc(-mid / std::sqrt(2.0));
    (cdf < probability ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Chi-square statistic of one edge's world-frame measurements [first, last).
double EdgeStatistic(const std::vector<internal::CorrelationMeasurement>& ms, size_t first,
                     size_t last) {
  Eigen::Matrix3d info_sum = Eigen::Matrix3d::Zero();
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  for (size_t k = first; k < last; ++k) {
    const Eigen::Matrix3d rt = ms[k].R_camera_world.transpose();
    const Eigen::Matrix3d info_world = rt * ms[k].information * ms[k].R_camera_world;
    info_sum += info_world;
    weighted += info_world * (rt * ms[k].z);
  }
  const Eigen::Vector3d mean = info_sum.inverse() * weighted;  // world-frame l_ij
  double chi2 = 0.0;
  for (size_t k = first; k < last; ++k) {
    const Eigen::Vector3d err = ms[k].z - ms[k].R_camera_world * mean;
    chi2 += err.dot(ms[k].information * err);
  }
  return chi2;
}

}  // namespace

double ChiSquareQuantile(int dof, double probability) {
  if (dof < 1 || !(probability > 0.0 && probability < 1.0)) {
    throw std::invalid_argument("ChiSquareQuantile: need dof >= 1 and 0 < p < 1");
  }
  const double k = dof;
  const double s = 2.0 / (9.0 * k);
  const double c = 1.0 - s + NormalQuantile(probability) * std::sqrt(s);
  return k * c * c * c;
}

CullingResult DirectEdgeTest(const CorrelationInput& input, const std::vector<GraphEdge>& edges,
                             double probability) {
  const auto ms = internal::BuildMeasurements(input, edges);  // grouped by edge
  CullingResult result;
  result.edge_kept.assign(edges.size(), true);
  result.edge_measurements.assign(edges.size(), 0);
  result.edge_inliers.assign(edges.size(), 0);
  result.edge_max_chi2.assign(edges.size(), 0.0);
  result.measurements = static_cast<int>(ms.size());
  std::vector<double> threshold_by_count;  // chi-square quantile per measurement count, cached
  for (size_t first = 0; first < ms.size();) {
    size_t last = first;
    while (last < ms.size() && ms[last].edge == ms[first].edge) ++last;
    const int e = ms[first].edge;
    const int count = static_cast<int>(last - first);
    result.edge_measurements[e] = count;
    result.edge_inliers[e] = count;
    if (count >= 2) {
      const double chi2 = EdgeStatistic(ms, first, last);
      result.edge_max_chi2[e] = chi2;
      if (threshold_by_count.size() <= static_cast<size_t>(count)) {
        const size_t old_size = threshold_by_count.size();
        threshold_by_count.resize(count + 1);
        for (size_t c = std::max<size_t>(old_size, 2); c <= static_cast<size_t>(count); ++c) {
          threshold_by_count[c] = ChiSquareQuantile(3 * (static_cast<int>(c) - 1), probability);
        }
      }
      if (chi2 > threshold_by_count[count]) {
        result.edge_kept[e] = false;
        result.edge_inliers[e] = 0;
        result.culled_measurements += count;
      }
    }
    first = last;
  }
  return result;
}

}  // namespace dslam
