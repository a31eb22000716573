#pragma once
// Internal to part mapping: the decimated depth grid the dynamic mask is grown on (and split on,
// region_split.cpp), the region growing itself, and the pixel measurement the carried points share
// (point_carrier.cpp).

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/core/objects_config.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/mapping/depth_change.h"
#include "dslam/mapping/dynamic_mask.h"

namespace dslam {

/// [m] depth of pixel (u, v) of `depth_m` (CV_32FC1) when valid: finite, above 0 and at most
/// `max_depth_m`; 0 when missing or outside the image.
double ValidPixelDepth(const cv::Mat& depth_m, int u, int v, double max_depth_m);

/// [m] raw pixel `uv_raw` [px] of `camera` at depth `z` [m] in its optical frame (undistorted
/// first).
Eigen::Vector3d BackProjectRawPixel(const PinholeCamera& camera, const Eigen::Vector2d& uv_raw,
                                    double z);

/// Cells of decimation x decimation pixels over one frame; a cell's depth and colour are those
/// of its centre pixel. Back-projected cell points are computed on first use and cached.
class CellGrid {
 public:
  CellGrid(const RgbdFrame& frame, const DynamicMaskConfig& config);

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  int size() const { return rows_ * cols_; }
  bool Inside(int r, int c) const { return r >= 0 && c >= 0 && r < rows_ && c < cols_; }

  /// Cell index of pixel (u, v) [px], -1 outside the grid.
  int CellOf(int u, int v) const;
  /// [m] valid depth of pixel (u, v) (within max_depth_m), 0 when missing or outside.
  double PixelDepth(int u, int v) const {
    return ValidPixelDepth(frame_.depth_m, u, v, max_depth_m_);
  }
  /// [m] depth of a cell's centre pixel, 0 when missing.
  double CellDepth(int cell) const { return depth_[cell]; }
  /// [m] largest depth difference of continuous neighbours at depth z [m].
  double DepthStep(double z) const { return step_m_ + step_ratio_ * z; }
  /// [m] raw pixel `uv_raw` [px] at depth `z` [m] in the optical frame (undistorted first).
  Eigen::Vector3d BackProjectPixel(const Eigen::Vector2d& uv_raw, double z) const {
    return BackProjectRawPixel(*frame_.camera, uv_raw, z);
  }
  /// [m] the cell's centre point in the optical frame (its depth must be valid).
  const Eigen::Vector3d& CellPoint(int cell) const;
  /// [m] CellPoint(cell) computed without caching it (for cells looked at once).
  Eigen::Vector3d CellPointOnce(int cell) const {
    const double z = depth_[cell];
    return Eigen::Vector3d(rays_[cell].x() * z, rays_[cell].y() * z, z);
  }
  /// [0, 1] the cell's centre colour (B, G, R).
  Eigen::Vector3d CellColour(int cell) const;

 private:
  const RgbdFrame& frame_;
  const std::vector<Eigen::Vector2d>& rays_;  ///< per cell: centre pixel's ray at unit depth
  int decimation_, rows_, cols_;
  double step_m_, step_ratio_, max_depth_m_;
  std::vector<double> depth_;
  mutable std::vector<Eigen::Vector3d> points_;
  mutable std::vector<uint8_t> has_point_;
};

/// What one region grows from.
struct RegionSeeds {
  uint16_t label = 0;
  std::vector<int> cells;                      ///< seed cells (may repeat)
  std::vector<PointId> points;                 ///< the points of the cluster
  std::vector<int> point_cells;                ///< each point's seed cell, -1 when none
  std::vector<Eigen::Vector3d> points_camera;  ///< [m] their positions, optical frame
  /// [m] box of the cluster's points, optical frame (empty until Include()).
  Eigen::Vector3d box_min = Eigen::Vector3d::Constant(1e300);
  Eigen::Vector3d box_max = Eigen::Vector3d::Constant(-1e300);
  double margin_m = 0.0;  ///< [m] how far the region may grow beyond the box

  /// Grows the box to hold `p_camera` [m, optical frame].
  void Include(const Eigen::Vector3d& p_camera) {
    box_min = box_min.cwiseMin(p_camera);
    box_max = box_max.cwiseMax(p_camera);
  }
};

/// Sums of a region's cells, giving its cell count, centroid, box and mean colour.
class RegionStatistics {
 public:
  /// Adds one cell at `p_world` [m] with `colour`.
  void Add(const Eigen::Vector3d& p_world, const Eigen::Vector3d& colour);
  /// Writes cells, box and, with at least one cell, centroid and mean colour into `region`.
  void WriteTo(DynamicRegion* region) const;

 private:
  int cells_ = 0;
  Eigen::Vector3d sum_world_ = Eigen::Vector3d::Zero(), sum_colour_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d min_world_ = Eigen::Vector3d::Constant(1e300);
  Eigen::Vector3d max_world_ = Eigen::Vector3d::Constant(-1e300);
};

/// Grows one region (breadth first, 4-neighbours, depth-continuous, within margin_m of the
/// seeds' box, never into `blocked` cells or cells already labelled) and writes its label into
/// `labels`; returns its statistics in the world frame of `T_world_camera`. `touched` receives
/// the labels of earlier regions it met across a depth-continuous cell border (the same surface).
DynamicRegion GrowRegion(const CellGrid& grid, const RegionSeeds& seeds,
                         const Eigen::Isometry3d& T_world_camera,
                         const std::vector<uint8_t>& blocked, cv::Mat* labels,
                         std::vector<uint16_t>* touched);

/// Adds region `from` to region `into` (statistics, points); relabels from's cells in `labels`.
void MergeRegion(const DynamicRegion& from, DynamicRegion* into, cv::Mat* labels);

/// Step 4 of dynamic_mask.h (in depth_change.cpp): grows the depth-change regions of the frame of
/// `grid` into `mask` (its labels and regions), never into `blocked` cells, and gives the cells
/// it labels the not verified static `points` in them.
void AddDepthChangeRegions(const CellGrid& grid, const DepthReference& reference,
                           const std::vector<ObservedPoint>& points,
                           const std::vector<uint8_t>& blocked,
                           const Eigen::Isometry3d& T_world_camera, const DynamicMaskConfig& config,
                           DynamicMask* mask);

}  // namespace dslam
