#include "cell_grid.h"

#include <algorithm>
#include <cmath>

namespace dslam {
namespace {

/// The unit-depth rays (x/z, y/z) of the cell centres of `camera` at `decimation`, undistorted
/// once per camera and decimation on each thread (the last ones are kept: a node or a dataset
/// has one camera, and Undistort iterates per pixel).
const std::vector<Eigen::Vector2d>& CellRays(const PinholeCamera& camera, int decimation) {
  struct Cache {
    std::vector<double> key;
    std::vector<Eigen::Vector2d> rays;
  };
  thread_local Cache cache;
  const Distortion& d = camera.distortion();
  const std::vector<double> key = {static_cast<double>(camera.width()),
                                   static_cast<double>(camera.height()),
                                   camera.fx(),
                                   camera.fy(),
                                   camera.cx(),
                                   camera.cy(),
                                   d.k1,
                                   d.k2,
                                   d.p1,
                                   d.p2,
                                   d.k3,
                                   static_cast<double>(decimation)};
  if (cache.key == key) return cache.rays;
  const int rows = camera.height() / decimation, cols = camera.width() / decimation;
  const int half = decimation / 2;
  cache.rays.resize(static_cast<size_t>(rows) * cols);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const Eigen::Vector2d uv_raw(c * decimation + half, r * decimation + half);
      const Eigen::Vector2d uv = d.IsZero() ? uv_raw : camera.Undistort(uv_raw);
      cache.rays[r * cols + c] = camera.BackProject(uv, 1.0).head<2>();
    }
  }
  cache.key = key;
  return cache.rays;
}

}  // namespace

CellGrid::CellGrid(const RgbdFrame& frame, const DynamicMaskConfig& config)
    : frame_(frame),
      rays_(CellRays(*frame.camera, config.decimation)),
      decimation_(config.decimation),
      rows_(frame.depth_m.rows / config.decimation),
      cols_(frame.depth_m.cols / config.decimation),
      step_m_(config.depth_step_m),
      step_ratio_(config.depth_step_ratio),
      max_depth_m_(config.max_depth_m),
      depth_(static_cast<size_t>(rows_) * cols_, 0.0),
      points_(depth_.size()),
      has_point_(depth_.size(), 0) {
  const int half = decimation_ / 2;
  for (int r = 0; r < rows_; ++r) {
    for (int c = 0; c < cols_; ++c) {
      depth_[r * cols_ + c] = PixelDepth(c * decimation_ + half, r * decimation_ + half);
    }
  }
}

int CellGrid::CellOf(int u, int v) const {
  const int r = v / decimation_, c = u / decimation_;
  return (u >= 0 && v >= 0 && Inside(r, c)) ? r * cols_ + c : -1;
}

double ValidPixelDepth(const cv::Mat& depth_m, int u, int v, double max_depth_m) {
  if (u < 0 || v < 0 || u >= depth_m.cols || v >= depth_m.rows) return 0.0;
  const float z = depth_m.at<float>(v, u);
  return (std::isfinite(z) && z > 0.0f && z <= max_depth_m) ? z : 0.0;
}

Eigen::Vector3d BackProjectRawPixel(const PinholeCamera& camera, const Eigen::Vector2d& uv_raw,
                                    double z) {
  const Eigen::Vector2d uv = camera.distortion().IsZero() ? uv_raw : camera.Undistort(uv_raw);
  return camera.BackProject(uv, z);
}

const Eigen::Vector3d& CellGrid::CellPoint(int cell) const {
  if (!has_point_[cell]) {
    points_[cell] = CellPointOnce(cell);
    has_point_[cell] = 1;
  }
  return points_[cell];
}

Eigen::Vector3d CellGrid::CellColour(int cell) const {
  const int half = decimation_ / 2;
  const int u = (cell % cols_) * decimation_ + half, v = (cell / cols_) * decimation_ + half;
  if (frame_.colour.type() == CV_8UC3) {
    const cv::Vec3b bgr = frame_.colour.at<cv::Vec3b>(v, u);
    return Eigen::Vector3d(bgr[0], bgr[1], bgr[2]) / 255.0;
  }
  return Eigen::Vector3d::Constant(frame_.colour.at<uint8_t>(v, u) / 255.0);
}

DynamicRegion GrowRegion(const CellGrid& grid, const RegionSeeds& seeds,
                         const Eigen::Isometry3d& T_world_camera,
                         const std::vector<uint8_t>& blocked, cv::Mat* labels,
                         std::vector<uint16_t>* touched) {
  DynamicRegion region;
  region.label = seeds.label;
  region.points = seeds.points;
  region.point_cells = seeds.point_cells;
  for (const Eigen::Vector3d& p : seeds.points_camera)
    region.points_world.push_back(T_world_camera * p);
  const Eigen::Vector3d box_min = seeds.box_min.array() - seeds.margin_m;
  const Eigen::Vector3d box_max = seeds.box_max.array() + seeds.margin_m;
  auto* label = labels->ptr<uint16_t>();
  std::vector<int> queue;
  for (int cell : seeds.cells) {
    if (label[cell] != 0) continue;
    label[cell] = seeds.label;
    queue.push_back(cell);
  }
  RegionStatistics statistics;
  for (size_t head = 0; head < queue.size(); ++head) {
    const int cell = queue[head];
    statistics.Add(T_world_camera * grid.CellPoint(cell), grid.CellColour(cell));
    const int r = cell / grid.cols(), c = cell % grid.cols();
    const int neighbours[4][2] = {{r - 1, c}, {r + 1, c}, {r, c - 1}, {r, c + 1}};
    for (const auto& rc : neighbours) {
      if (!grid.Inside(rc[0], rc[1])) continue;
      const int next = rc[0] * grid.cols() + rc[1];
      const double z = grid.CellDepth(next);
      if (label[next] == seeds.label || blocked[next] || z <= 0.0) continue;
      if (std::abs(z - grid.CellDepth(cell)) > grid.DepthStep(z)) continue;
      if (label[next] != 0) {
        if (std::find(touched->begin(), touched->end(), label[next]) == touched->end()) {
          touched->push_back(label[next]);
        }
        continue;
      }
      const Eigen::Vector3d& p = grid.CellPoint(next);
      if ((p.array() < box_min.array()).any() || (p.array() > box_max.array()).any()) continue;
      label[next] = seeds.label;
      queue.push_back(next);
    }
  }
  statistics.WriteTo(&region);
  return region;
}

void RegionStatistics::Add(const Eigen::Vector3d& p_world, const Eigen::Vector3d& colour) {
  ++cells_;
  sum_world_ += p_world;
  sum_colour_ += colour;
  min_world_ = min_world_.cwiseMin(p_world);
  max_world_ = max_world_.cwiseMax(p_world);
}

void RegionStatistics::WriteTo(DynamicRegion* region) const {
  region->cells = cells_;
  region->min_world = min_world_;
  region->max_world = max_world_;
  if (cells_ > 0) {
    region->centroid_world = sum_world_ / cells_;
    region->mean_colour = sum_colour_ / cells_;
  }
}

void MergeRegion(const DynamicRegion& from, DynamicRegion* into, cv::Mat* labels) {
  const int cells = from.cells + into->cells;
  if (cells > 0) {
    into->centroid_world =
        (from.centroid_world * from.cells + into->centroid_world * into->cells) / cells;
    into->mean_colour = (from.mean_colour * from.cells + into->mean_colour * into->cells) / cells;
  }
  into->min_world = into->min_world.cwiseMin(from.min_world);
  into->max_world = into->max_world.cwiseMax(from.max_world);
  into->cells = cells;
  into->points.insert(into->points.end(), from.points.begin(), from.points.end());
  into->points_world.insert(into->points_world.end(), from.points_world.begin(),
                            from.points_world.end());
  into->point_cells.insert(into->point_cells.end(), from.point_cells.begin(),
                           from.point_cells.end());
  labels->setTo(into->label, *labels == from.label);
}

}  // namespace dslam
