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

// Calls f(observation of a, observation of b) for every frame both point lists (sorted by frame)
// have an observation in.
template <typename F>
void ForCommonFrames(const std::vector<std::pair<int, int>>& a,
                     const std::vector<std::pair<int, int>>& b, F&& f) {
  size_t ia = 0, ib = 0;
  while (ia < a.size() && ib < b.size()) {
    if (a[ia].first < b[ib].first) {
      ++ia;
    } else if (b[ib].first < a[ia].first) {
      ++ib;
    } else {
      f(a[ia++].second, b[ib++].second);
    }
  }
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
  size_t count = 0;  // one pass to count, so that the vector is allocated once
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    const GraphEdge& edge = edges[e];
    if (edge.i < 0 || edge.j >= num_points || edge.i >= edge.j) {
      throw std::invalid_argument("edge " + std::to_string(e) + " is not 0 <= i < j < N");
    }
    ForCommonFrames(by_point[edge.i], by_point[edge.j], [&count](int, int) { ++count; });
  }
  std::vector<CorrelationMeasurement> measurements;
  measurements.reserve(count);
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    ForCommonFrames(by_point[edges[e].i], by_point[edges[e].j], [&](int oi_index, int oj_index) {
      const PointObservation& oi = input.observations[oi_index];
      const PointObservation& oj = input.observations[oj_index];
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
    });
  }
  return measurements;
}

}  // namespace internal
}  // namespace dslam
