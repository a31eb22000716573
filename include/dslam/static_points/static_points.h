#pragma once
// Static point determination (paper Sec. IV and V-A, Algorithm 1): Delaunay graph over the
// points -> inconsistent edge culling with point-correlation measurements -> connected
// components -> the component with the largest convex-hull volume is static.
// The caller chooses the points and frames: the front end (front_end_static_points.h) passes
// the current frame's tracked points with their measurements in the current frame and in
// keyframes spread over the window; the back end (backend/window_static_points.h) passes the
// window's marked points with their measurements in the window's keyframes (Algorithm 1).

#include <vector>

#include "dslam/core/config.h"
#include "dslam/static_points/correlation_problem.h"
#include "dslam/static_points/point_graph.h"
#include "dslam/static_points/segmentation.h"
#include "dslam/static_points/static_points_stats.h"

namespace dslam {

/// With fewer matched points with depth (or window points) the front and back end skip static
/// point determination: fewer than 4 points span no tetrahedron (3D Delaunay cell).
constexpr int kMinGraphPoints = 8;

/// Everything DetermineStaticPoints found.
struct StaticPointsResult {
  std::vector<PointLabel> labels;   ///< per input point
  std::vector<int> component;       ///< component id per input point
  std::vector<GraphEdge> edges;     ///< Delaunay graph
  std::vector<bool> edge_kept;      ///< parallel to edges; false: inconsistent
  std::vector<bool> edge_verified;  ///< parallel to edges; measured in >= min_edge_measurements
  std::vector<Eigen::Vector3d> points_world;  ///< [m] optimised (least_squares) or input points
  int static_component = -1;                  ///< -1: no static component (all kUndecided)
  StaticPointsStats stats;                    ///< timings and counts
};

/// A component other than the static one is only evidence of motion when a tested edge joins it
/// to the static component (and was culled: otherwise they would be one component). Components
/// cut off merely because their edges were untested carry no evidence: their kDynamic/kIsolated
/// labels become kUnverified. Without this, a static region the graph happens to cut off is
/// labelled dynamic.
void RequireEvidenceAgainstStatic(const std::vector<GraphEdge>& edges,
                                  const std::vector<bool>& edge_verified,
                                  const std::vector<int>& component, int static_component,
                                  std::vector<PointLabel>* labels);

/// Runs the three steps on `input` (points, fixed camera poses, observations). The graph is
/// built over input.points_world; volumes use the optimised points. Throws
/// std::invalid_argument on inconsistent indices.
StaticPointsResult DetermineStaticPoints(const CorrelationInput& input,
                                         const StaticPointsConfig& config);

/// The same with the graph given: `edges` must be BuildDelaunayGraph(input.points_world)
/// (built earlier, e.g. in parallel with other work); `graph_ms` [ms] is reported as its time.
StaticPointsResult DetermineStaticPoints(const CorrelationInput& input,
                                         std::vector<GraphEdge> edges, double graph_ms,
                                         const StaticPointsConfig& config);

}  // namespace dslam
