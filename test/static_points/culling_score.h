#pragma once
// Metrics shared by the static point determination tests.

#include <vector>

#include "dslam/static_points/point_graph.h"

namespace dslam {
namespace testing_util {

/// Culled-edge quality against the ground truth: an edge is "boundary" when exactly one endpoint
/// is dynamic; those should be culled, all others kept.
struct CullingScore {
  int edges = 0;
  int boundary = 0;
  int culled = 0;
  int culled_boundary = 0;
  double Recall() const { return boundary ? static_cast<double>(culled_boundary) / boundary : 1.0; }
  double Precision() const { return culled ? static_cast<double>(culled_boundary) / culled : 1.0; }
  double CulledFraction() const { return edges ? static_cast<double>(culled) / edges : 0.0; }
  int FalselyCulled() const { return culled - culled_boundary; }
};

inline CullingScore ScoreCulling(const std::vector<GraphEdge>& edges, const std::vector<bool>& kept,
                                 const std::vector<bool>& is_dynamic) {
  CullingScore s;
  s.edges = static_cast<int>(edges.size());
  for (size_t e = 0; e < edges.size(); ++e) {
    const bool boundary = is_dynamic[edges[e].i] != is_dynamic[edges[e].j];
    s.boundary += boundary;
    s.culled += !kept[e];
    s.culled_boundary += boundary && !kept[e];
  }
  return s;
}

}  // namespace testing_util
}  // namespace dslam
