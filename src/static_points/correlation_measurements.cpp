#include "correlation_measurements.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/LU>
#include <opencv2/core/utility.hpp>

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

// z_ijk = y_ik - y_jk of edge `e` in the frame of `oi` and `oj`, with C_ijk^-1 (paper Eq.
// meas_con_imp; plus the rotation uncertainty's part when the input has it).
CorrelationMeasurement Measurement(const CorrelationInput& input, int e, const PointObservation& oi,
                                   const PointObservation& oj) {
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
  return m;
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
  // One pass counts each edge's measurements (its slots in the output), a second fills them,
  // edges in parallel.
  std::vector<size_t> first(edges.size() + 1, 0);
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    const GraphEdge& edge = edges[e];
    if (edge.i < 0 || edge.j >= num_points || edge.i >= edge.j) {
      throw std::invalid_argument("edge " + std::to_string(e) + " is not 0 <= i < j < N");
    }
    size_t count = 0;
    ForCommonFrames(by_point[edge.i], by_point[edge.j], [&count](int, int) { ++count; });
    first[e + 1] = first[e] + count;
  }
  std::vector<CorrelationMeasurement> measurements(first.back());
  cv::parallel_for_(cv::Range(0, static_cast<int>(edges.size())), [&](const cv::Range& range) {
    for (int e = range.start; e < range.end; ++e) {
      size_t slot = first[e];
      ForCommonFrames(by_point[edges[e].i], by_point[edges[e].j], [&](int oi_index, int oj_index) {
        measurements[slot++] =
            Measurement(input, e, input.observations[oi_index], input.observations[oj_index]);
      });
    }
  });
  return measurements;
}

}  // namespace internal
}  // namespace dslam
