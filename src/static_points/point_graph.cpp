#include "dslam/static_points/point_graph.h"

#include <algorithm>
#include <iterator>
#include <utility>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

namespace dslam {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<int, Kernel>;
using DataStructure =
    CGAL::Triangulation_data_structure_3<VertexBase,
                                         CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, DataStructure>;

GraphEdge MakeEdge(int a, int b) { return a < b ? GraphEdge{a, b} : GraphEdge{b, a}; }

}  // namespace

std::vector<GraphEdge> BuildDelaunayGraph(const std::vector<Eigen::Vector3d>& points) {
  std::vector<std::pair<Kernel::Point_3, int>> input;
  input.reserve(points.size());
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const Eigen::Vector3d& p = points[i];
    if (!p.allFinite()) continue;
    input.emplace_back(Kernel::Point_3(p.x(), p.y(), p.z()), i);
  }
  // Spatially sorted bulk insertion; a point equal to an existing vertex is not inserted and
  // keeps the info of the first one inserted, which is not necessarily the smallest index.
  Delaunay triangulation(input.begin(), input.end());

  // Each vertex's finite neighbours, every edge once (from its smaller-index end): cheaper than
  // finite_edges_begin(), which circulates around each edge to visit it once.
  std::vector<GraphEdge> edges;
  edges.reserve(triangulation.number_of_vertices() * 8);
  std::vector<Delaunay::Vertex_handle> neighbours;
  for (auto v = triangulation.finite_vertices_begin(); v != triangulation.finite_vertices_end();
       ++v) {
    neighbours.clear();
    triangulation.finite_adjacent_vertices(v, std::back_inserter(neighbours));
    for (const auto& w : neighbours) {
      if (v->info() < w->info()) edges.push_back(GraphEdge{v->info(), w->info()});
    }
  }
  // Duplicates: connect each input point that did not become a vertex to the vertex at its place.
  if (triangulation.number_of_vertices() < input.size()) {
    for (const auto& [point, index] : input) {
      const auto vertex = triangulation.nearest_vertex(point);
      if (vertex->info() != index) edges.push_back(MakeEdge(vertex->info(), index));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace dslam
