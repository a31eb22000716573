#include "dslam/static_points/segmentation.h"

#include <algorithm>
#include <numeric>

#include <Eigen/Geometry>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

namespace dslam {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

int FindRoot(std::vector<int>* parent, int i) {
  while ((*parent)[i] != i) {
    (*parent)[i] = (*parent)[(*parent)[i]];  // path halving
    i = (*parent)[i];
  }
  return i;
}

// Sum of signed tetrahedra (face, centroid) of a closed triangulated mesh.
double MeshVolume(const Mesh& mesh) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    centroid += Eigen::Vector3d(p.x(), p.y(), p.z());
  }
  centroid /= static_cast<double>(mesh.number_of_vertices());
  double volume = 0.0;
  for (const auto f : mesh.faces()) {
    std::vector<Eigen::Vector3d> corners;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      const auto& p = mesh.point(v);
      corners.emplace_back(Eigen::Vector3d(p.x(), p.y(), p.z()) - centroid);
    }
    for (size_t k = 1; k + 1 < corners.size(); ++k) {  // fan, in case a face is not a triangle
      volume += corners[0].dot(corners[k].cross(corners[k + 1])) / 6.0;
    }
  }
  return std::abs(volume);
}

}  // namespace

std::vector<int> ConnectedComponents(int num_points, const std::vector<GraphEdge>& edges,
                                     const std::vector<bool>& edge_kept) {
  std::vector<int> parent(num_points);
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t e = 0; e < edges.size(); ++e) {
    if (!edge_kept.empty() && !edge_kept[e]) continue;
    const int a = FindRoot(&parent, edges[e].i);
    const int b = FindRoot(&parent, edges[e].j);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // root = smallest member
  }
  std::vector<int> id_of_root(num_points, -1);
  std::vector<int> component(num_points);
  int count = 0;
  for (int i = 0; i < num_points; ++i) {
    const int root = FindRoot(&parent, i);
    if (id_of_root[root] < 0) id_of_root[root] = count++;
    component[i] = id_of_root[root];
  }
  return component;
}

int ComponentCount(const std::vector<int>& component_of_point) {
  return component_of_point.empty()
             ? 0
             : *std::max_element(component_of_point.begin(), component_of_point.end()) + 1;
}

double ConvexHullVolume(const std::vector<Eigen::Vector3d>& points) {
  if (points.size() < 4) return 0.0;
  std::vector<Kernel::Point_3> input;
  input.reserve(points.size());
  for (const auto& p : points) input.emplace_back(p.x(), p.y(), p.z());
  // Coplanar (or collinear) input has no 3D hull: the hull of a degenerate set is not closed.
  const auto& a = input[0];
  bool three_dimensional = false;
  for (size_t i = 1; i < input.size() && !three_dimensional; ++i) {
    for (size_t j = i + 1; j < input.size() && !three_dimensional; ++j) {
      if (CGAL::collinear(a, input[i], input[j])) continue;
      for (size_t k = j + 1; k < input.size(); ++k) {
        if (!CGAL::coplanar(a, input[i], input[j], input[k])) {
          three_dimensional = true;
          break;
        }
      }
      break;  // a, i, j span a plane: the k-loop decided
    }
  }
  if (!three_dimensional) return 0.0;
  Mesh hull;
  CGAL::convex_hull_3(input.begin(), input.end(), hull);
  return MeshVolume(hull);
}

StaticSelection SelectStaticComponent(const std::vector<Eigen::Vector3d>& points_world,
                                      const std::vector<int>& component_of_point,
                                      const StaticSelectionOptions& options) {
  const int num_components = ComponentCount(component_of_point);
  std::vector<std::vector<Eigen::Vector3d>> members(num_components);
  for (size_t i = 0; i < component_of_point.size(); ++i) {
    members[component_of_point[i]].push_back(points_world[i]);
  }
  StaticSelection out;
  out.component_volumes.assign(num_components, 0.0);
  out.component_sizes.assign(num_components, 0);
  int best = -1;
  auto better = [&out](int a, int b) {  // is component a preferred over b?
    if (b < 0) return true;
    if (out.component_volumes[a] != out.component_volumes[b]) {
      return out.component_volumes[a] > out.component_volumes[b];
    }
    return out.component_sizes[a] > out.component_sizes[b];
  };
  for (int c = 0; c < num_components; ++c) {
    out.component_sizes[c] = static_cast<int>(members[c].size());
    if (out.component_sizes[c] < options.min_component_points) continue;
    out.component_volumes[c] = ConvexHullVolume(members[c]);
    if (better(c, best)) best = c;
  }
  if (best >= 0 && out.component_sizes[best] >= options.min_static_points) {
    out.static_component = best;
  }
  out.labels.resize(component_of_point.size());
  for (size_t i = 0; i < component_of_point.size(); ++i) {
    const int c = component_of_point[i];
    if (out.static_component < 0) {
      out.labels[i] = PointLabel::kUndecided;
    } else if (c == out.static_component) {
      out.labels[i] = PointLabel::kStatic;
    } else {
      out.labels[i] = out.component_sizes[c] >= 2 ? PointLabel::kDynamic : PointLabel::kIsolated;
    }
  }
  return out;
}

}  // namespace dslam
