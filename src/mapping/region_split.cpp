#include "dslam/mapping/region_split.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "cell_grid.h"

namespace dslam {
namespace {

/// Most two-means iterations over a region's cells.
constexpr int kShareIterations = 10;

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

/// Two-means (Lloyd) of `values` from `centres`, at most `max_iterations` rounds: `group` gets 0
/// or 1 per value and `centres` the groups' means. False, with the last round's groups and the
/// centres before it, when a group empties.
template <typename Vector>
bool TwoMeansFrom(const std::vector<Vector>& values, int max_iterations,
                  std::array<Vector, 2>* centres, std::vector<uint8_t>* group) {
  using Scalar = typename Vector::Scalar;
  group->assign(values.size(), 0);
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    bool changed = iteration == 0;
    std::array<Vector, 2> sums = {Vector::Zero(), Vector::Zero()};
    int counts[2] = {0, 0};
    for (size_t i = 0; i < values.size(); ++i) {
      const uint8_t g = (values[i] - (*centres)[1]).squaredNorm() <
                        (values[i] - (*centres)[0]).squaredNorm();
      changed |= g != (*group)[i];
      (*group)[i] = g;
      sums[g] += values[i];
      ++counts[g];
    }
    if (counts[0] == 0 || counts[1] == 0) return false;
    for (int g = 0; g < 2; ++g) (*centres)[g] = sums[g] / static_cast<Scalar>(counts[g]);
    if (!changed) break;
  }
  return true;
}

/// Two-means of `values` started from the 10th and 90th percentiles along their principal axis:
/// the group (0 or 1) of each value; empty when the values do not spread.
std::vector<uint8_t> TwoMeans(const std::vector<Eigen::Vector3d>& values) {
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
  std::array<Eigen::Vector3d, 2> centres = {values[along[n / 10].second],
                                            values[along[n - 1 - n / 10].second]};
  if ((centres[0] - centres[1]).squaredNorm() == 0.0) return {};
  std::vector<uint8_t> group;
  if (!TwoMeansFrom(values, 20, &centres, &group)) return {};
  return group;
}

/// [m] the 10th and 90th percentiles of `values`.
std::pair<double, double> Range(std::vector<double> values) {
  const size_t n = values.size();
  std::nth_element(values.begin(), values.begin() + n / 10, values.end());
  const double low = values[n / 10];
  std::nth_element(values.begin(), values.begin() + (n - 1 - n / 10), values.end());
  return {low, values[n - 1 - n / 10]};
}

/// Two world positions [m] around which a region is split.
using Centres = std::array<Eigen::Vector3d, 2>;

/// The per-axis median positions of two groups of `region`'s points whose velocities differ
/// (steps 1-3 of region_split.h); none when its points move as one thing.
std::optional<Centres> VelocityCentres(const DynamicRegion& region,
                                       const std::deque<PointPositions>& history, double stamp_s,
                                       const ObjectsConfig& config) {
  std::vector<Eigen::Vector3d> velocities, positions;
  for (size_t i = 0; i < region.points.size(); ++i) {
    Eigen::Vector3d v;
    if (!PointVelocity(region.points[i], region.points_world[i], history, stamp_s,
                       config.motion_baseline_s, config, &v)) {
      continue;
    }
    velocities.push_back(v);
    positions.push_back(region.points_world[i]);
  }
  if (static_cast<int>(velocities.size()) < 2 * kSplitMinPoints) return std::nullopt;
  const std::vector<uint8_t> group = TwoMeans(velocities);
  if (group.empty()) return std::nullopt;
  std::vector<Eigen::Vector3d> members[2], where[2];
  for (size_t k = 0; k < group.size(); ++k) {
    members[group[k]].push_back(velocities[k]);
    where[group[k]].push_back(positions[k]);
  }
  for (const auto& m : members) {
    if (static_cast<int>(m.size()) < kSplitMinPoints) return std::nullopt;
  }
  if ((AxisMedians(members[0]) - AxisMedians(members[1])).norm() < config.split_speed_mps) {
    return std::nullopt;
  }
  return Centres{AxisMedians(where[0]), AxisMedians(where[1])};
}

/// The two farthest-apart `predicted` track positions [m, world] inside `region`'s box, when
/// they are at least split_min_distance_m apart (step 0 of region_split.h).
std::optional<Centres> TrackCentres(const DynamicRegion& region,
                                    const std::vector<Eigen::Vector3d>& predicted,
                                    const ObjectsConfig& config) {
  std::vector<Eigen::Vector3d> inside;
  for (const Eigen::Vector3d& p : predicted) {
    if ((p.array() >= region.min_world.array()).all() &&
        (p.array() <= region.max_world.array()).all()) {
      inside.push_back(p);
    }
  }
  double farthest = config.split_min_distance_m;
  std::optional<Centres> centres;
  for (size_t i = 0; i < inside.size(); ++i) {
    for (size_t j = i + 1; j < inside.size(); ++j) {
      const double d = (inside[i] - inside[j]).norm();
      if (d < farthest) continue;
      farthest = d;
      centres = Centres{inside[i], inside[j]};
    }
  }
  return centres;
}

/// [m] a point's position across the view: optical x and z (depth), not the image's vertical.
Eigen::Vector2f Across(const Eigen::Vector3d& p_camera) {
  return Eigen::Vector2f(static_cast<float>(p_camera.x()), static_cast<float>(p_camera.z()));
}

/// A region's cells shared out between two parts side by side (step 4 of region_split.h).
struct CellParts {
  std::vector<int> cells;                  ///< the region's cells (row * cols + col)
  std::vector<Eigen::Vector2f> across;     ///< [m] their points' Across()
  std::vector<uint8_t> part;               ///< 0 or 1 per cell
  std::array<Eigen::Vector2f, 2> centres;  ///< [m] the parts' mean Across()
};

/// Two-means of the Across() positions of `region`'s cells (labels), started from
/// `centres_world`: the parts can only lie side by side in the view, never one above the other.
CellParts ShareCells(const CellGrid& grid, const Eigen::Isometry3d& T_camera_world,
                     const DynamicRegion& region, const cv::Mat& labels,
                     const Centres& centres_world) {
  CellParts parts;
  for (int g = 0; g < 2; ++g) parts.centres[g] = Across(T_camera_world * centres_world[g]);
  const auto* label = labels.ptr<uint16_t>();
  for (int cell = 0; cell < grid.size(); ++cell) {
    if (label[cell] != region.label) continue;
    parts.cells.push_back(cell);
    parts.across.push_back(Across(grid.CellPointOnce(cell)));
  }
  TwoMeansFrom(parts.across, kShareIterations, &parts.centres, &parts.part);
  return parts;
}

/// A region's parts and the part of each of its points.
struct Split {
  CellParts cells;
  std::vector<uint8_t> point_part;  ///< per point of the region: 0 or 1
};

/// The part of each of `region`'s points: its cell's, or the nearer centre's without a cell.
std::vector<uint8_t> PointParts(const DynamicRegion& region, const CellParts& parts,
                                const Eigen::Isometry3d& T_camera_world) {
  std::vector<uint8_t> point_part(region.points.size());
  for (size_t i = 0; i < region.points.size(); ++i) {
    const int cell = region.point_cells[i];
    const auto at = std::lower_bound(parts.cells.begin(), parts.cells.end(), cell);
    if (cell >= 0 && at != parts.cells.end() && *at == cell) {
      point_part[i] = parts.part[at - parts.cells.begin()];
      continue;
    }
    const Eigen::Vector2f p = Across(T_camera_world * region.points_world[i]);
    point_part[i] = (p - parts.centres[1]).squaredNorm() < (p - parts.centres[0]).squaredNorm();
  }
  return point_part;
}

/// Whether `parts` are two things side by side (step 5 of region_split.h): each holds
/// kSplitMinPoints of the region's points, the horizontal ranges (10th-90th percentile of the
/// cells' optical x) overlap by at most split_max_overlap of the narrower, and the parts' mean
/// positions are at least split_min_distance_m apart.
bool SideBySide(const CellParts& parts, const std::vector<uint8_t>& point_part,
                const ObjectsConfig& config) {
  const auto in_one = std::count(point_part.begin(), point_part.end(), 1);
  const auto in_zero = static_cast<std::ptrdiff_t>(point_part.size()) - in_one;
  if (std::min(in_zero, in_one) < kSplitMinPoints) return false;
  if ((parts.centres[0] - parts.centres[1]).norm() < config.split_min_distance_m) return false;
  std::vector<double> x[2];
  for (size_t k = 0; k < parts.cells.size(); ++k) x[parts.part[k]].push_back(parts.across[k].x());
  if (x[0].empty() || x[1].empty()) return false;
  const auto a = Range(std::move(x[0])), b = Range(std::move(x[1]));
  const double overlap = std::min(a.second, b.second) - std::max(a.first, b.first);
  const double narrower = std::min(a.second - a.first, b.second - b.first);
  return overlap <= config.split_max_overlap * narrower;
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

/// Splits `mask->regions[index]` into itself (part 0) and a new region (part 1).
void SplitRegion(const CellGrid& grid, const Eigen::Isometry3d& T_world_camera, size_t index,
                 const CellParts& parts, const std::vector<uint8_t>& point_part,
                 DynamicMask* mask) {
  DynamicRegion& region = mask->regions[index];
  DynamicRegion kept, part;
  kept.label = region.label;
  part.label = static_cast<uint16_t>(mask->regions.size() + 1);
  auto* label = mask->labels.ptr<uint16_t>();
  for (size_t k = 0; k < parts.cells.size(); ++k) {
    if (parts.part[k] == 1) label[parts.cells[k]] = part.label;
  }
  for (size_t i = 0; i < region.points.size(); ++i) {
    DynamicRegion& target = point_part[i] == 1 ? part : kept;
    target.points.push_back(region.points[i]);
    target.points_world.push_back(region.points_world[i]);
    target.point_cells.push_back(region.point_cells[i]);
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
  // The parts of `region` around `centres` when they stand side by side (steps 4-5).
  const auto side_by_side = [&](const DynamicRegion& region,
                                const std::optional<Centres>& centres) -> std::optional<Split> {
    if (!centres || region.cells < 2) return std::nullopt;
    if (!grid) grid = std::make_unique<CellGrid>(frame, mask_config);
    Split split{ShareCells(*grid, T_camera_world, region, mask->labels, *centres), {}};
    split.point_part = PointParts(region, split.cells, T_camera_world);
    if (!SideBySide(split.cells, split.point_part, objects_config)) return std::nullopt;
    return split;
  };
  for (size_t i = 0; i < mask->regions.size(); ++i) {
    while (parts[origin[i]] < kMaxSplitParts) {
      const DynamicRegion& region = mask->regions[i];
      std::optional<Split> split =
          side_by_side(region, TrackCentres(region, predicted, objects_config));
      if (!split) {
        split = side_by_side(region, VelocityCentres(region, history, stamp_s, objects_config));
      }
      if (!split) break;
      SplitRegion(*grid, T_world_camera, i, split->cells, split->point_part, mask);
      origin.push_back(origin[i]);
      ++parts[origin[i]];
      ++splits;  // region i (its kept part) is tried again
    }
  }
  return splits;
}

}  // namespace dslam
