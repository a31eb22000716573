#pragma once
// Bounding the graph: above a point count the Delaunay graph (whose construction grows faster
// than linearly with the points: 1.3 ms for 300 points, 8.9 ms for 1000 on the project's
// machine) is built over a subset, and the points left out take the label of their nearest graph
// point. The caller chooses which points must stay (front_end_static_points.h: the unsettled
// ones) and thins the rest with SpatiallyEvenSubset.

#include <vector>

#include <Eigen/Core>

#include "dslam/static_points/static_points.h"

namespace dslam {

/// Indices into `uv` [px] of min(uv.size(), max_points) points spread evenly over the points'
/// bounding box: it is cut into about max_points square cells, and the cells hand out their
/// points round-robin (cell by cell in row-major order, each cell's points by index) until
/// max_points are chosen. Returned in increasing order.
std::vector<int> SpatiallyEvenSubset(const std::vector<Eigen::Vector2d>& uv, int max_points);

/// For each point of `others` [m], the index of the nearest point of `graph_points` [m] (same
/// frame); -1 when `graph_points` is empty.
std::vector<int> NearestGraphPoints(const std::vector<Eigen::Vector3d>& graph_points,
                                    const std::vector<Eigen::Vector3d>& others);

/// The label a point left out of the graph takes from its nearest graph point: kStatic and
/// kDynamic carry over, anything else becomes kUnverified (no tested edge either way).
PointLabel InheritedLabel(PointLabel nearest);

}  // namespace dslam
