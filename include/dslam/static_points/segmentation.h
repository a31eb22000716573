#pragma once
// Step 3 of static point determination (paper Sec. IV-C): connected components of the culled
// graph, and "the component with the largest volume is static".

#include <vector>

#include <Eigen/Core>

#include "dslam/static_points/point_graph.h"

namespace dslam {

/// Component id per point (0..count-1, numbered by smallest member index) over the edges whose
/// `edge_kept` flag is true (`edge_kept` empty: all edges). Union-find, no recursion. A point
/// without kept edges is a singleton component.
std::vector<int> ConnectedComponents(int num_points, const std::vector<GraphEdge>& edges,
                                     const std::vector<bool>& edge_kept);

/// [-] number of components in `component_of_point` (component id per point, ids 0..count-1 as
/// ConnectedComponents numbers them): the largest id + 1, 0 when there are no points.
int ComponentCount(const std::vector<int>& component_of_point);

/// [m^3] volume of the convex hull of `points` (CGAL convex_hull_3). 0 for fewer than 4 points
/// and for collinear or coplanar points.
double ConvexHullVolume(const std::vector<Eigen::Vector3d>& points);

/// Label of a point after static point determination.
enum class PointLabel {
  kStatic,      ///< member of the selected static (largest-volume) component
  kDynamic,     ///< member of another component with at least 2 points
  kIsolated,    ///< no kept edge (all its correlations were inconsistent, or it had none)
  kUndecided,   ///< no static component could be selected (see SelectStaticComponent)
  kUnverified,  ///< none of its edges had enough measurements to be tested (DetermineStaticPoints)
};

/// Rules for choosing the static component.
struct StaticSelectionOptions {
  int min_component_points = 4;  ///< [-] smaller components never count as the static one
  int min_static_points = 10;    ///< [-] if the largest-volume component is smaller: no decision
};

/// Outcome of the static component selection.
struct StaticSelection {
  std::vector<PointLabel> labels;         ///< per point
  std::vector<double> component_volumes;  ///< [m^3] per component id (convex hull)
  std::vector<int> component_sizes;       ///< [-] points per component id
  int static_component = -1;              ///< component id, -1 when none was selected
};

/// Chooses the component with the largest convex-hull volume among those with at least
/// min_component_points points as static (paper). When its size is below min_static_points
/// (e.g. a person filling the view) no component is chosen: every point is kUndecided and the
/// caller should not trust this frame's segmentation (fall back to a robust pose). Ties in
/// volume: more points, then lower id.
StaticSelection SelectStaticComponent(const std::vector<Eigen::Vector3d>& points_world,
                                      const std::vector<int>& component_of_point,
                                      const StaticSelectionOptions& options);

}  // namespace dslam
