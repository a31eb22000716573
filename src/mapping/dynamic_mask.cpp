#include "dslam/mapping/dynamic_mask.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include <Eigen/Geometry>

#include "cell_grid.h"

namespace dslam {
namespace {

/// An unmarked point measured again in this frame.
struct MovingPoint {
  PointId id = -1;
  Eigen::Vector3d p_camera;  ///< [m] optical frame, from this frame's depth
  int cell = -1;             ///< its cell index in the grid
};

std::vector<MovingPoint> MeasureUnmarkedPoints(const CellGrid& grid,
                                               const std::vector<ObservedPoint>& points) {
  std::vector<MovingPoint> moving;
  for (const ObservedPoint& point : points) {
    if (point.is_static) continue;
    const int u = static_cast<int>(std::lround(point.uv_raw.x()));
    const int v = static_cast<int>(std::lround(point.uv_raw.y()));
    const double z = grid.PixelDepth(u, v);
    if (z <= 0.0) continue;
    moving.push_back({point.id, grid.BackProjectPixel(point.uv_raw, z), grid.CellOf(u, v)});
  }
  return moving;
}

/// The axis-aligned box of a cluster's points, optical frame [m].
Eigen::AlignedBox3d BoxOf(const std::vector<MovingPoint>& points, const std::vector<int>& members) {
  Eigen::AlignedBox3d box;
  for (int i : members) box.extend(points[i].p_camera);
  return box;
}

/// Merges clusters whose boxes, grown by `margin_m`, intersect (the parts of one person that
/// single linkage split where its points are sparse), until no two do.
void MergeOverlappingClusters(const std::vector<MovingPoint>& points, double margin_m,
                              std::vector<std::vector<int>>* clusters) {
  for (bool merged = true; merged;) {
    merged = false;
    for (size_t a = 0; a < clusters->size() && !merged; ++a) {
      Eigen::AlignedBox3d box_a = BoxOf(points, (*clusters)[a]);
      box_a.min().array() -= margin_m;
      box_a.max().array() += margin_m;
      for (size_t b = a + 1; b < clusters->size() && !merged; ++b) {
        if (!box_a.intersects(BoxOf(points, (*clusters)[b]))) continue;
        auto& target = (*clusters)[a];
        target.insert(target.end(), (*clusters)[b].begin(), (*clusters)[b].end());
        clusters->erase(clusters->begin() + b);
        merged = true;
      }
    }
  }
}

int FindRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

/// Single-linkage clusters of the points (indices into `points`) that `keep` accepts, largest
/// first.
std::vector<std::vector<int>> ClusterPoints(
    const std::vector<MovingPoint>& points, double distance_m, double margin_m,
    const std::function<bool(const std::vector<int>&)>& keep) {
  const int n = static_cast<int>(points.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  const double distance2 = distance_m * distance_m;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if ((points[i].p_camera - points[j].p_camera).squaredNorm() <= distance2) {
        parent[FindRoot(parent, i)] = FindRoot(parent, j);
      }
    }
  }
  std::vector<std::vector<int>> by_root(n);
  for (int i = 0; i < n; ++i) by_root[FindRoot(parent, i)].push_back(i);
  std::vector<std::vector<int>> clusters;
  for (auto& members : by_root) {
    if (!members.empty()) clusters.push_back(std::move(members));
  }
  MergeOverlappingClusters(points, margin_m, &clusters);
  clusters.erase(std::remove_if(clusters.begin(), clusters.end(),
                                [&](const std::vector<int>& c) { return !keep(c); }),
                 clusters.end());
  std::stable_sort(clusters.begin(), clusters.end(),
                   [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return clusters;
}

/// The cell of `point` or, when that cell's depth is not continuous with the point's (a keypoint
/// on a depth edge), the 8-neighbour whose depth is closest and continuous; -1 when none is.
int SeedCell(const CellGrid& grid, const MovingPoint& point) {
  const double z = point.p_camera.z();
  int best = -1;
  double best_dz = grid.DepthStep(z);
  const int r0 = point.cell / grid.cols(), c0 = point.cell % grid.cols();
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      const int r = r0 + dr, c = c0 + dc;
      if (!grid.Inside(r, c)) continue;
      const double dz = std::abs(grid.CellDepth(r * grid.cols() + c) - z);
      if (grid.CellDepth(r * grid.cols() + c) > 0.0 && dz <= best_dz &&
          (best == -1 || dz < best_dz || (dr == 0 && dc == 0))) {
        best = r * grid.cols() + c;
        best_dz = dz;
      }
    }
  }
  return best;
}

}  // namespace

int DynamicMask::CellAt(int u, int v) const {
  if (labels.empty() || u < 0 || v < 0) return -1;
  const int r = v / decimation, c = u / decimation;
  if (r >= labels.rows || c >= labels.cols) return -1;
  return r * labels.cols + c;
}

uint16_t DynamicMask::LabelAt(int u, int v) const {
  const int cell = CellAt(u, v);
  return cell < 0 ? 0 : labels.ptr<uint16_t>()[cell];
}

double DynamicMask::MaskedShare() const {
  if (labels.empty()) return 0.0;
  return static_cast<double>(cv::countNonZero(labels)) / static_cast<double>(labels.total());
}

DynamicMask ComputeDynamicMask(const RgbdFrame& frame, const Eigen::Isometry3d& T_world_camera,
                               const std::vector<ObservedPoint>& points,
                               const DynamicMaskConfig& config) {
  return ComputeDynamicMask(frame, T_world_camera, points, config, {}, 0.0, 0);
}

DynamicMask ComputeDynamicMask(const RgbdFrame& frame, const Eigen::Isometry3d& T_world_camera,
                               const std::vector<ObservedPoint>& points,
                               const DynamicMaskConfig& config,
                               const std::vector<Eigen::Vector3d>& near_world, double near_m,
                               int near_min_points, const DepthReference* reference) {
  const CellGrid grid(frame, config);
  DynamicMask mask;
  mask.decimation = config.decimation;
  mask.labels = cv::Mat::zeros(grid.rows(), grid.cols(), CV_16UC1);
  std::vector<uint8_t> blocked(grid.size(), 0);
  for (const ObservedPoint& point : points) {
    if (!point.is_static || point.is_candidate) continue;
    const int cell = grid.CellOf(static_cast<int>(std::lround(point.uv_raw.x())),
                                 static_cast<int>(std::lround(point.uv_raw.y())));
    if (cell >= 0) blocked[cell] = 1;
  }
  const std::vector<MovingPoint> moving = MeasureUnmarkedPoints(grid, points);
  std::vector<Eigen::Vector3d> near_camera;
  for (const Eigen::Vector3d& p : near_world) near_camera.push_back(T_world_camera.inverse() * p);
  const auto keep = [&](const std::vector<int>& cluster) {
    const int n = static_cast<int>(cluster.size());
    if (n >= config.min_cluster_points) return true;
    if (n < near_min_points || near_camera.empty()) return false;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int i : cluster) mean += moving[i].p_camera / n;
    for (const Eigen::Vector3d& p : near_camera) {
      if ((p - mean).norm() <= near_m) return true;
    }
    return false;
  };
  for (const std::vector<int>& cluster :
       ClusterPoints(moving, config.cluster_distance_m, config.margin_m, keep)) {
    RegionSeeds seeds;
    seeds.label = static_cast<uint16_t>(mask.regions.size() + 1);
    seeds.margin_m = config.margin_m;
    for (int i : cluster) {
      seeds.Include(moving[i].p_camera);
      const int cell = SeedCell(grid, moving[i]);
      if (cell >= 0) seeds.cells.push_back(cell);
      seeds.point_cells.push_back(cell);
      seeds.points.push_back(moving[i].id);
      seeds.points_camera.push_back(moving[i].p_camera);
    }
    std::vector<uint16_t> touched;
    DynamicRegion region = GrowRegion(grid, seeds, T_world_camera, blocked, &mask.labels, &touched);
    if (region.cells == 0) continue;
    if (touched.empty()) {
      mask.regions.push_back(std::move(region));
    } else {  // the same surface as an earlier region: one moving thing
      MergeRegion(region, &mask.regions[*std::min_element(touched.begin(), touched.end()) - 1],
                  &mask.labels);
    }
  }
  if (reference != nullptr && !reference->empty()) {
    AddDepthChangeRegions(grid, *reference, points, blocked, T_world_camera, config, &mask);
  }
  return mask;
}

}  // namespace dslam
