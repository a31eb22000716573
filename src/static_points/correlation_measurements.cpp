#include "correlation_measurements.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/LU>

#include "dslam/core/geometry.h"

namespace dslam {
namespace internal {
namespace {

// Per point: (frame, observation index), sorted by frame.
std::vector<std::vector<std::pair<int, int>>> ObservationsByPoint(const CorrelationInput& input) {
  const int num_points = static_cast<int>(input.points_world.size());
  const int num_frames = static_cast<int>(input.T_camera_world.size());
  std::vector<std::vector<std::pair<int, int>>> by_point(num_points);
  for (int o = 0; o < static_cast<int>(input.observations.size()); ++o) {
    const PointObservation& obs = input.observations[o];
    if (obs.point < 0 || obs.point >= num_points || obs.frame < 0 || obs.frame >= num_frames) {
      throw std::invalid_argument("observation " + std::to_string(o) + " has point " +
                                  std::to_string(obs.point) + ", frame " +
                                  std::to_string(obs.frame) + " out of range");
    }
    by_point[obs.point].emplace_back(obs.frame, o);
  }
  for (auto& list : by_point) std::sort(list.begin(), list.end());
  return by_point;
}

}  // namespace

std::vector<CorrelationMeasurement> BuildMeasurements(const CorrelationInput& input,
                                                      const std::vector<GraphEdge>& edges) {
  if (!input.rotation_covariance.empty() &&
      input.rotation_covariance.size() != input.T_camera_world.size()) {
    throw std::invalid_argument("rotation_covariance needs one matrix per frame");
  }
  const auto by_point = ObservationsByPoint(input);
  const int num_points = static_cast<int>(by_point.size());
  std::vector<CorrelationMeasurement> measurements;
  measurements.reserve(edges.size() * 2);
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    const GraphEdge& edge = edges[e];
    if (edge.i < 0 || edge.j >= num_points || edge.i >= edge.j) {
      throw std::invalid_argument("edge " + std::to_string(e) + " is not 0 <= i < j < N");
    }
    const auto& a = by_point[edge.i];
    const auto& b = by_point[edge.j];
    size_t ia = 0, ib = 0;
    while (ia < a.size() && ib < b.size()) {
      if (a[ia].first < b[ib].first) {
        ++ia;
        continue;
      }
      if (b[ib].first < a[ia].first) {
        ++ib;
        continue;
      }
      const PointObservation& oi = input.observations[a[ia].second];
      const PointObservation& oj = input.observations[b[ib].second];
      CorrelationMeasurement m;
      m.edge = e;
      m.frame = oi.frame;
      m.z = oi.y_camera - oj.y_camera;
      Eigen::Matrix3d covariance = oi.covariance + oj.covariance;
      if (!input.rotation_covariance.empty()) {
        covariance += Skew(m.z) * input.rotation_covariance[oi.frame] * Skew(m.z).transpose();
      }
      m.information = covariance.inverse();
      m.R_camera_world = input.T_camera_world[oi.frame].linear();
      measurements.push_back(m);
      ++ia;
      ++ib;
    }
  }
  return measurements;
}

}  // namespace internal
}  // namespace dslam
