#pragma once
// Voxel hashing for the map measurement (map_metrics.h): downsampling a point stream to one
// centroid per voxel, and an exact fixed-radius neighbour test over a point set (a hash grid of
// cells as large as the radius: every point within the radius of a query lies in the 27 cells
// around the query's cell, and each candidate's distance is tested exactly).

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

namespace dslam {

/// Integer cell of `p` [m] for cells of size `cell_m` [m] (floor(p / cell_m)), each coordinate
/// clamped to [-2^20, 2^20 - 1] (points beyond share the border cells; tests stay exact).
Eigen::Vector3i CellOf(const Eigen::Vector3d& p, double cell_m);

/// A 64-bit key of a cell returned by CellOf (21 bits per coordinate).
uint64_t CellKey(const Eigen::Vector3i& cell);

/// Accumulates points and keeps, per voxel, the centroid of the points that fell in it.
class VoxelDownsampler {
 public:
  /// `voxel_m` [m] > 0: voxel edge length. Throws std::invalid_argument otherwise.
  explicit VoxelDownsampler(double voxel_m);

  /// Adds a point [m]; non-finite points are ignored.
  void Add(const Eigen::Vector3d& p);

  size_t size() const { return voxels_.size(); }  ///< occupied voxels

  /// One centroid [m] per occupied voxel, sorted by voxel key (independent of the adding order
  /// up to floating-point rounding of the sums).
  std::vector<Eigen::Vector3d> Centroids() const;

 private:
  struct Sum {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    long count = 0;
  };
  double voxel_m_;
  std::unordered_map<uint64_t, Sum> voxels_;
};

/// Exact test whether a point set has a point within a fixed radius of a query.
class RadiusIndex {
 public:
  /// Indexes `points` [m] (non-finite ones are left out) for queries of radius `radius_m` [m] > 0.
  /// Throws std::invalid_argument for a radius that is not positive and finite.
  RadiusIndex(const std::vector<Eigen::Vector3d>& points, double radius_m);

  /// True when some indexed point p has |p - query| <= radius_m.
  bool AnyWithin(const Eigen::Vector3d& query) const;

  size_t size() const { return points_.size(); }  ///< indexed points

 private:
  double radius_m_;
  double cell_m_;  ///< [m] radius_m_ enlarged by 1e-9 relative: rounding never skips a cell
  std::vector<Eigen::Vector3d> points_;                      ///< grouped by cell
  std::unordered_map<uint64_t, std::pair<int, int>> cells_;  ///< key -> [begin, end) in points_
};

}  // namespace dslam
