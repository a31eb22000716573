#include "dslam/static_points/graph_subset.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dslam {

std::vector<int> SpatiallyEvenSubset(const std::vector<Eigen::Vector2d>& uv, int max_points) {
  const int n = static_cast<int>(uv.size());
  std::vector<int> chosen;
  if (max_points <= 0) return chosen;
  if (n <= max_points) {
    for (int i = 0; i < n; ++i) chosen.push_back(i);
    return chosen;
  }
  Eigen::Vector2d lo = uv[0], hi = uv[0];
  for (const Eigen::Vector2d& p : uv) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector2d extent = (hi - lo).cwiseMax(1.0);
  const double side = std::sqrt(extent.x() * extent.y() / max_points);
  const int cols = static_cast<int>(extent.x() / side) + 1;
  const int rows = static_cast<int>(extent.y() / side) + 1;
  std::vector<std::vector<int>> cells(static_cast<size_t>(cols) * rows);
  for (int i = 0; i < n; ++i) {
    const int c = std::min(cols - 1, static_cast<int>((uv[i].x() - lo.x()) / side));
    const int r = std::min(rows - 1, static_cast<int>((uv[i].y() - lo.y()) / side));
    cells[static_cast<size_t>(r) * cols + c].push_back(i);
  }
  for (size_t round = 0; static_cast<int>(chosen.size()) < max_points; ++round) {
    for (const std::vector<int>& cell : cells) {
      if (round < cell.size() && static_cast<int>(chosen.size()) < max_points) {
        chosen.push_back(cell[round]);
      }
    }
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

std::vector<int> NearestGraphPoints(const std::vector<Eigen::Vector3d>& graph_points,
                                    const std::vector<Eigen::Vector3d>& others) {
  std::vector<int> nearest(others.size(), -1);
  for (size_t o = 0; o < others.size(); ++o) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t g = 0; g < graph_points.size(); ++g) {
      const double d2 = (graph_points[g] - others[o]).squaredNorm();
      if (d2 < best) {
        best = d2;
        nearest[o] = static_cast<int>(g);
      }
    }
  }
  return nearest;
}

PointLabel InheritedLabel(PointLabel nearest) {
  return nearest == PointLabel::kStatic || nearest == PointLabel::kDynamic
             ? nearest
             : PointLabel::kUnverified;
}

}  // namespace dslam
