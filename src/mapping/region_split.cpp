#include "dslam/mapping/region_split.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <Eigen/Eigenvalues>

#include "cell_grid.h"

namespace dslam {
namespace {

Eigen::Vector3d AxisMedians(const std::vector<Eigen::Vector3d>& values) {
  Eigen::Vector3d median;
  for (int a = 0; a < 3; ++a) {
    std::vector<double> axis;
    for (const Eigen::Vector3d& v : values) axis.push_back(v[a]);
    const size_t mid = axis.size() / 2;
    std::nth_element(axis.begin(), axis.begin() + mid, axis.end());
    median[a] = axis[mid];
  }
  return median;
}

/// Two-means of `values` started from the 10th and 90th percentiles along their principal axis:
/// the group (0 or 1) of each value; empty when the values do not spread.
std::vector<int> TwoMeans(const std::vector<Eigen::Vector3d>& values) {
  const int n = static_cast<int>(values.size());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : values) mean += v;
  mean /= n;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& v : values) covariance += (v - mean) * (v - mean).transpose();
  const Eigen::Vector3d axis =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors().col(2);
  std::vector<std::pair<double, int>> along;
  for (int i = 0; i < n; ++i) along.emplace_back(axis.dot(values[i] - mean), i);
  std::sort(along.begin(), along.end());
  Eigen::Vector3d centres[2] = {values[along[n / 10].second], values[along[n - 1 - n / 10].second]};
  if ((centres[0] - centres[1]).squaredNorm() == 0.0) return {};
  std::vector<int> group(n, -1);
  for (int iteration = 0; iteration < 20; ++iteration) {
    bool changed = false;
    Eigen::Vector3d sums[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    int counts[2] = {0, 0};
    for (int i = 0; i < n; ++i) {
      const int g = (values[i] - centres[1]).squaredNorm() < (values[i] - centres[0]).squaredNorm();
      changed |= g != group[i];
      group[i] = g;
      sums[g] += values[i];
      ++counts[g];
    }
    if (counts[0] == 0 || counts[1] == 0) return {};
    for (int g = 0; g < 2; ++g) centres[g] = sums[g] / counts[g];
    if (!changed) break;
  }
  return group;
}

/// Shares the cells labelled `from` out between `from` (group 0) and `to` (group 1): breadth
/// first over the region's 4-connected cells from the seed cells of both groups at once.
void ShareCells(const std::vector<int>& seeds0, const std::vector<int>& seeds1, uint16_t from,
                uint16_t to, cv::Mat* labels) {
  const int cols = labels->cols, rows = labels->rows;
  auto* label = labels->ptr<uint16_t>();
  std::vector<int8_t> part(static_cast<size_t>(rows) * cols, -1);
  std::vector<int> queue;
  for (int g = 0; g < 2; ++g) {
    for (int cell : g == 0 ? seeds0 : seeds1) {
      if (label[cell] != from || part[cell] != -1) continue;
      part[cell] = static_cast<int8_t>(g);
      queue.push_back(cell);
    }
  }
  for (size_t head = 0; head < queue.size(); ++head) {
    const int cell = queue[head];
    const int r = cell / cols, c = cell % cols;
    const int neighbours[4][2] = {{r - 1, c}, {r + 1, c}, {r, c - 1}, {r, c + 1}};
    for (const auto& rc : neighbours) {
      if (rc[0] < 0 || rc[1] < 0 || rc[0] >= rows || rc[1] >= cols) continue;
      const int next = rc[0] * cols + rc[1];
      if (label[next] != from || part[next] != -1) continue;
      part[next] = part[cell];
      queue.push_back(next);
    }
  }
  for (int cell : queue) {
    if (part[cell] == 1) label[cell] = to;
  }
}

/// Recomputes the cell statistics (cells, centroid, box, colour) of `region` from `labels`.
void RecomputeStatistics(const CellGrid& grid, const cv::Mat& labels,
                         const Eigen::Isometry3d& T_world_camera, DynamicRegion* region) {
  const auto* label = labels.ptr<uint16_t>();
  RegionStatistics statistics;
  for (int cell = 0; cell < grid.size(); ++cell) {
    if (label[cell] != region->label) continue;
    statistics.Add(T_world_camera * grid.CellPoint(cell), grid.CellColour(cell));
  }
  statistics.WriteTo(region);
}

/// [m] the 10th and 90th percentiles of `values`.
std::pair<double, double> Range(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return {values[n / 10], values[n - 1 - n / 10]};
}

/// Whether the two groups (0, 1; -1: neither) of `region`'s points are two things side by
/// side: the overlap of their horizontal ranges (optical x) is at most split_max_overlap of the
/// narrower range (parts of one thing moving differently, a leg under the body, overlap more),
/// and their per-axis median positions are at least split_min_distance_m apart.
bool SideBySide(const DynamicRegion& region, const std::vector<int>& groups,
                const Eigen::Isometry3d& T_camera_world, const ObjectsConfig& config) {
  std::vector<double> x[2];
  std::vector<Eigen::Vector3d> positions[2];
  for (size_t i = 0; i < groups.size(); ++i) {
    if (groups[i] < 0) continue;
    x[groups[i]].push_back((T_camera_world * region.points_world[i]).x());
    positions[groups[i]].push_back(region.points_world[i]);
  }
  if (x[0].empty() || x[1].empty()) return false;
  const auto a = Range(x[0]), b = Range(x[1]);
  const double overlap = std::min(a.second, b.second) - std::max(a.first, b.first);
  const double narrower = std::min(a.second - a.first, b.second - b.first);
  return overlap <= config.split_max_overlap * narrower &&
         (AxisMedians(positions[0]) - AxisMedians(positions[1])).norm() >=
             config.split_min_distance_m;
}

/// The velocity groups of `region`'s points (-1: no velocity), or empty when it is one thing.
std::vector<int> VelocityGroups(const DynamicRegion& region,
                                const std::deque<PointPositions>& history, double stamp_s,
                                const Eigen::Isometry3d& T_camera_world,
                                const ObjectsConfig& config) {
  std::vector<Eigen::Vector3d> velocities;
  std::vector<int> index;
  for (size_t i = 0; i < region.points.size(); ++i) {
    Eigen::Vector3d v;
    if (!PointVelocity(region.points[i], region.points_world[i], history, stamp_s,
                       config.motion_baseline_s, config, &v)) {
      continue;
    }
    velocities.push_back(v);
    index.push_back(static_cast<int>(i));
  }
  if (static_cast<int>(velocities.size()) < 2 * config.split_min_points) return {};
  const std::vector<int> group = TwoMeans(velocities);
  if (group.empty()) return {};
  std::vector<Eigen::Vector3d> members[2];
  for (size_t k = 0; k < group.size(); ++k) members[group[k]].push_back(velocities[k]);
  for (const auto& m : members) {
    if (static_cast<int>(m.size()) < config.split_min_points) return {};
  }
  if ((AxisMedians(members[0]) - AxisMedians(members[1])).norm() < config.split_speed_mps) {
    return {};
  }
  std::vector<int> groups(region.points.size(), -1);
  for (size_t k = 0; k < group.size(); ++k) groups[index[k]] = group[k];
  if (!SideBySide(region, groups, T_camera_world, config)) return {};
  return groups;
}

/// The groups of `region`'s points by the nearer of the two farthest-apart `predicted` track
/// positions [m, world] inside the region's box, when those are at least split_min_distance_m
/// apart and both groups have split_min_points points; empty otherwise.
std::vector<int> TrackGroups(const DynamicRegion& region,
                             const std::vector<Eigen::Vector3d>& predicted,
                             const Eigen::Isometry3d& T_camera_world, const ObjectsConfig& config) {
  std::vector<Eigen::Vector3d> inside;
  for (const Eigen::Vector3d& p : predicted) {
    if ((p.array() >= region.min_world.array()).all() &&
        (p.array() <= region.max_world.array()).all()) {
      inside.push_back(p);
    }
  }
  double farthest = config.split_min_distance_m;
  int a = -1, b = -1;
  for (size_t i = 0; i < inside.size(); ++i) {
    for (size_t j = i + 1; j < inside.size(); ++j) {
      const double d = (inside[i] - inside[j]).norm();
      if (d < farthest) continue;
      farthest = d;
      a = static_cast<int>(i);
      b = static_cast<int>(j);
    }
  }
  if (a < 0) return {};
  std::vector<int> groups(region.points.size());
  int counts[2] = {0, 0};
  for (size_t i = 0; i < region.points.size(); ++i) {
    const Eigen::Vector3d& p = region.points_world[i];
    groups[i] = (p - inside[b]).squaredNorm() < (p - inside[a]).squaredNorm();
    ++counts[groups[i]];
  }
  if (std::min(counts[0], counts[1]) < config.split_min_points) return {};
  if (!SideBySide(region, groups, T_camera_world, config)) return {};
  return groups;
}

/// Splits `mask->regions[index]` by `groups` (VelocityGroups) into itself and a new region.
void SplitRegion(const CellGrid& grid, const Eigen::Isometry3d& T_world_camera, size_t index,
                 const std::vector<int>& groups, DynamicMask* mask) {
  DynamicRegion& region = mask->regions[index];
  DynamicRegion part;
  part.label = static_cast<uint16_t>(mask->regions.size() + 1);
  std::vector<int> seeds[2];
  for (size_t i = 0; i < groups.size(); ++i) {
    if (groups[i] >= 0 && region.point_cells[i] >= 0)
      seeds[groups[i]].push_back(region.point_cells[i]);
  }
  ShareCells(seeds[0], seeds[1], region.label, part.label, &mask->labels);
  DynamicRegion kept;
  kept.label = region.label;
  const auto* label = mask->labels.ptr<uint16_t>();
  for (size_t i = 0; i < groups.size(); ++i) {
    const int cell = region.point_cells[i];
    const bool to_part =
        groups[i] == 1 || (groups[i] == -1 && cell >= 0 && label[cell] == part.label);
    DynamicRegion& target = to_part ? part : kept;
    target.points.push_back(region.points[i]);
    target.points_world.push_back(region.points_world[i]);
    target.point_cells.push_back(cell);
  }
  RecomputeStatistics(grid, mask->labels, T_world_camera, &kept);
  RecomputeStatistics(grid, mask->labels, T_world_camera, &part);
  region = std::move(kept);
  mask->regions.push_back(std::move(part));
}

}  // namespace

int SplitRegions(const RgbdFrame& frame, const Eigen::Isometry3d& T_world_camera,
                 const std::deque<PointPositions>& history, double stamp_s,
                 const std::vector<Eigen::Vector3d>& predicted,
                 const DynamicMaskConfig& mask_config, const ObjectsConfig& objects_config,
                 DynamicMask* mask) {
  if (mask->regions.empty()) return 0;
  std::unique_ptr<CellGrid> grid;
  std::vector<int> parts(mask->regions.size(), 1);  // per region: parts of its original region
  std::vector<size_t> origin(mask->regions.size());
  for (size_t i = 0; i < origin.size(); ++i) origin[i] = i;
  int splits = 0;
  const Eigen::Isometry3d T_camera_world = T_world_camera.inverse();
  for (size_t i = 0; i < mask->regions.size();) {
    std::vector<int> groups;
    if (parts[origin[i]] < kMaxSplitParts) {
      groups = TrackGroups(mask->regions[i], predicted, T_camera_world, objects_config);
      if (groups.empty()) {
        groups = VelocityGroups(mask->regions[i], history, stamp_s, T_camera_world, objects_config);
      }
    }
    if (groups.empty()) {
      ++i;
      continue;
    }
    if (!grid) grid = std::make_unique<CellGrid>(frame, mask_config);
    SplitRegion(*grid, T_world_camera, i, groups, mask);
    origin.push_back(origin[i]);
    ++parts[origin[i]];
    ++splits;  // region i (its kept part) is tried again
  }
  return splits;
}

}  // namespace dslam
