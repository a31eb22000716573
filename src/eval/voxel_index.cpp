// Voxel hashing for the map measurement (voxel_index.h).
#include "dslam/eval/voxel_index.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dslam {
namespace {

constexpr int kCellLimit = 1 << 20;  ///< cells per coordinate: [-kCellLimit, kCellLimit)

void CheckSize(double size_m, const char* what) {
  if (!(size_m > 0.0) || !std::isfinite(size_m)) {
    throw std::invalid_argument(std::string(what) + " must be positive and finite");
  }
}

}  // namespace

Eigen::Vector3i CellOf(const Eigen::Vector3d& p, double cell_m) {
  Eigen::Vector3i cell;
  for (int k = 0; k < 3; ++k) {
    const double c = std::floor(p[k] / cell_m);
    cell[k] = static_cast<int>(std::min<double>(std::max<double>(c, -kCellLimit), kCellLimit - 1));
  }
  return cell;
}

uint64_t CellKey(const Eigen::Vector3i& cell) {
  uint64_t key = 0;
  for (int k = 0; k < 3; ++k) {
    key = (key << 21) | static_cast<uint64_t>(cell[k] + kCellLimit);
  }
  return key;
}

VoxelDownsampler::VoxelDownsampler(double voxel_m) : voxel_m_(voxel_m) {
  CheckSize(voxel_m, "voxel size");
}

void VoxelDownsampler::Add(const Eigen::Vector3d& p) {
  if (!p.allFinite()) return;
  Sum& s = voxels_[CellKey(CellOf(p, voxel_m_))];
  s.sum += p;
  ++s.count;
}

std::vector<Eigen::Vector3d> VoxelDownsampler::Centroids() const {
  std::vector<std::pair<uint64_t, Eigen::Vector3d>> keyed;
  keyed.reserve(voxels_.size());
  for (const auto& [key, s] : voxels_) keyed.emplace_back(key, s.sum / s.count);
  std::sort(keyed.begin(), keyed.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Eigen::Vector3d> centroids;
  centroids.reserve(keyed.size());
  for (const auto& entry : keyed) centroids.push_back(entry.second);
  return centroids;
}

RadiusIndex::RadiusIndex(const std::vector<Eigen::Vector3d>& points, double radius_m)
    : radius_m_(radius_m), cell_m_(radius_m * (1.0 + 1e-9)) {
  CheckSize(radius_m, "radius");
  std::vector<std::pair<uint64_t, Eigen::Vector3d>> keyed;
  keyed.reserve(points.size());
  for (const Eigen::Vector3d& p : points) {
    if (p.allFinite()) keyed.emplace_back(CellKey(CellOf(p, cell_m_)), p);
  }
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  points_.reserve(keyed.size());
  for (size_t i = 0; i < keyed.size(); ++i) {
    points_.push_back(keyed[i].second);
    const int index = static_cast<int>(i);
    auto [it, inserted] = cells_.try_emplace(keyed[i].first, index, index + 1);
    if (!inserted) it->second.second = index + 1;
  }
}

bool RadiusIndex::AnyWithin(const Eigen::Vector3d& query) const {
  if (!query.allFinite()) return false;
  const Eigen::Vector3i centre = CellOf(query, cell_m_);
  const double r2 = radius_m_ * radius_m_;
  for (int dx = -1; dx <= 1; ++dx) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dz = -1; dz <= 1; ++dz) {
        const Eigen::Vector3i cell = centre + Eigen::Vector3i(dx, dy, dz);
        if ((cell.array() < -kCellLimit).any() || (cell.array() >= kCellLimit).any()) continue;
        const auto it = cells_.find(CellKey(cell));
        if (it == cells_.end()) continue;
        for (int i = it->second.first; i < it->second.second; ++i) {
          if ((points_[i] - query).squaredNorm() <= r2) return true;
        }
      }
    }
  }
  return false;
}

}  // namespace dslam
