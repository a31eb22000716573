#pragma once
// Step 1 of static point determination (paper Sec. IV-A, "Graph Initialization"): the graph of
// point correlations is the edge set of the 3D Delaunay triangulation of the map points.

#include <vector>

#include <Eigen/Core>

namespace dslam {

/// An undirected edge l_ij = p_i - p_j between two points (indices into the point list), i < j.
struct GraphEdge {
  int i = 0;  ///< smaller point index
  int j = 0;  ///< larger point index

  bool operator==(const GraphEdge& o) const { return i == o.i && j == o.j; }
  bool operator<(const GraphEdge& o) const { return i < o.i || (i == o.i && j < o.j); }
};

/// Unique edges (i < j, sorted) of the 3D Delaunay triangulation (CGAL, exact predicates) of
/// `points` [m, any common frame]. Degenerate input is handled as follows:
/// - fewer than 2 distinct points: no edges;
/// - all points collinear or coplanar: the edges of the lower-dimensional Delaunay triangulation
///   (a chain along the line, a 2D Delaunay triangulation in the plane);
/// - exact duplicates: only the first occurrence takes part; every later duplicate gets one edge
///   to that first occurrence, so it falls into the same connected component.
/// Non-finite points get no edges.
std::vector<GraphEdge> BuildDelaunayGraph(const std::vector<Eigen::Vector3d>& points);

}  // namespace dslam
