#include "dslam/mapping/depth_change.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>
#include <utility>

#include "cell_grid.h"
#include "dslam/core/depth_uncertainty.h"

namespace dslam {
namespace {

/// [s] stamps closer than this to a full interval count as a full interval (30 Hz stamps are not
/// exact multiples of the interval).
constexpr double kStampTolerance_s = 1e-3;

/// Per block of `block_px` x `block_px` pixels of `depth_m` (CV_32FC1 [m]) the depth of its
/// centre pixel (the pixel CellGrid gives its cells; the last pixel row or column for a partial
/// block) when it is at least `min_depth_m`, infinity otherwise (NaN, infinity, 0: none).
cv::Mat CentreDepths(const cv::Mat& depth_m, int block_px, double min_depth_m) {
  const float inf = std::numeric_limits<float>::infinity();
  cv::Mat blocks((depth_m.rows + block_px - 1) / block_px, (depth_m.cols + block_px - 1) / block_px,
                 CV_32FC1);
  const int half = block_px / 2;
  for (int r = 0; r < blocks.rows; ++r) {
    const float* row = depth_m.ptr<float>(std::min(r * block_px + half, depth_m.rows - 1));
    float* out = blocks.ptr<float>(r);
    for (int c = 0; c < blocks.cols; ++c) {
      const float d = row[std::min(c * block_px + half, depth_m.cols - 1)];
      out[c] = (d >= min_depth_m && d < inf) ? d : inf;
    }
  }
  return blocks;
}

/// The cells of `grid` on every `stride`-th row and column that are neither labelled nor
/// blocked, have a depth and are changed against `reference` (1); all others 0.
std::vector<uint8_t> ChangedCells(const CellGrid& grid, const DepthReference& reference,
                                  const std::vector<uint8_t>& blocked, const uint16_t* label,
                                  const Eigen::Isometry3d& T_world_camera, int stride) {
  std::vector<int> cells;
  std::vector<Eigen::Vector3d> points;
  cells.reserve(grid.size() / (stride * stride) + grid.cols());
  points.reserve(cells.capacity());
  for (int r = 0; r < grid.rows(); r += stride) {
    for (int c = 0; c < grid.cols(); c += stride) {
      const int cell = r * grid.cols() + c;
      if (label[cell] != 0 || blocked[cell] || grid.CellDepth(cell) <= 0.0) continue;
      cells.push_back(cell);
      points.push_back(grid.CellPointOnce(cell));
    }
  }
  const std::vector<uint8_t> test = reference.ForFrame(T_world_camera).ChangedAll(points);
  std::vector<uint8_t> changed(grid.size(), 0);
  for (size_t i = 0; i < cells.size(); ++i) changed[cells[i]] = test[i];
  return changed;
}

/// Groups of changed cells (ChangedCells at `stride`) connected to their neighbours `stride`
/// cells away in the four directions with a continuous depth (DepthStep per cell of distance),
/// covering at least `min_cells` cells (stride^2 per changed cell) each, largest first.
std::vector<std::vector<int>> ChangedGroups(const CellGrid& grid, std::vector<uint8_t> changed,
                                            int stride, int min_cells) {
  std::vector<std::vector<int>> groups;
  for (int start = 0; start < grid.size(); ++start) {
    if (!changed[start]) continue;
    changed[start] = 0;
    std::vector<int> group = {start};
    for (size_t head = 0; head < group.size(); ++head) {
      const int cell = group[head];
      const int r = cell / grid.cols(), c = cell % grid.cols();
      const int neighbours[4][2] = {
          {r - stride, c}, {r + stride, c}, {r, c - stride}, {r, c + stride}};
      for (const auto& rc : neighbours) {
        if (!grid.Inside(rc[0], rc[1])) continue;
        const int next = rc[0] * grid.cols() + rc[1];
        const double z = grid.CellDepth(next);
        if (!changed[next] || std::abs(z - grid.CellDepth(cell)) > stride * grid.DepthStep(z)) {
          continue;
        }
        changed[next] = 0;
        group.push_back(next);
      }
    }
    if (static_cast<int>(group.size()) * stride * stride >= min_cells) {
      groups.push_back(std::move(group));
    }
  }
  std::stable_sort(groups.begin(), groups.end(),
                   [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return groups;
}

/// Gives each region from `first_new` on (those the depth-change step made; their cells were all
/// unlabelled before it) the not verified static points (not yet in a region) in its cells whose
/// depth is continuous with their cell's.
void AttachPoints(const CellGrid& grid, const std::vector<ObservedPoint>& points, size_t first_new,
                  const Eigen::Isometry3d& T_world_camera, DynamicMask* mask) {
  if (mask->regions.size() == first_new) return;  // none made, or all merged into earlier ones
  std::unordered_set<PointId> taken;
  bool have_taken = false;  // `taken` is filled on the first point that needs it
  const uint16_t* label = mask->labels.ptr<uint16_t>();
  for (const ObservedPoint& point : points) {
    if (point.is_static && !point.is_candidate) continue;
    const int u = static_cast<int>(std::lround(point.uv_raw.x()));
    const int v = static_cast<int>(std::lround(point.uv_raw.y()));
    const int cell = grid.CellOf(u, v);
    if (cell < 0 || label[cell] <= first_new) continue;
    const double z = grid.PixelDepth(u, v);
    if (z <= 0.0 || std::abs(z - grid.CellDepth(cell)) > grid.DepthStep(z)) continue;
    if (!have_taken) {
      for (const DynamicRegion& region : mask->regions)
        taken.insert(region.points.begin(), region.points.end());
      have_taken = true;
    }
    if (!taken.insert(point.id).second) continue;
    DynamicRegion& region = mask->regions[label[cell] - 1];
    region.points.push_back(point.id);
    region.points_world.push_back(T_world_camera * grid.BackProjectPixel(point.uv_raw, z));
    region.point_cells.push_back(cell);
  }
}

/// The label of the first region of `mask` whose world box comes within `margin_m` [m] of
/// `region`'s, 0 when none does.
uint16_t NearRegion(const DynamicMask& mask, const DynamicRegion& region, double margin_m) {
  for (const DynamicRegion& other : mask.regions) {
    if (((other.min_world.array() - margin_m) <= region.max_world.array()).all() &&
        ((other.max_world.array() + margin_m) >= region.min_world.array()).all()) {
      return other.label;
    }
  }
  return 0;
}

}  // namespace

DepthReference::DepthReference(const DynamicMaskConfig& mask, const DepthNoiseConfig& noise)
    : mask_(mask), noise_(noise) {}

void DepthReference::Add(const RgbdFrame& frame, const Eigen::Isometry3d& T_world_camera,
                         double stamp_s) {
  if (!views_.empty() && stamp_s < last_stamp_s_) views_.clear();
  if (!views_.empty() &&
      stamp_s - last_stamp_s_ < mask_.depth_change_interval_s - kStampTolerance_s) {
    return;
  }
  views_.emplace_back(frame.camera, T_world_camera, mask_.decimation,
                      CentreDepths(frame.depth_m, mask_.decimation, noise_.min_depth_m));
  last_stamp_s_ = stamp_s;
  while (static_cast<int>(views_.size()) > mask_.depth_change_references) views_.pop_front();
}

FreeSpaceTolerance DepthReference::Tolerance(double depth_m) const {
  FreeSpaceTolerance tolerance;
  tolerance.margin_m =
      mask_.depth_change_margin_m + mask_.depth_change_sigma_factor * DepthSigma(depth_m, noise_);
  tolerance.margin_ratio = 0.0;
  tolerance.min_depth_m = noise_.min_depth_m;
  tolerance.max_depth_m = mask_.max_depth_m;
  return tolerance;
}

bool DepthReference::Changed(const Eigen::Vector3d& p_world, double depth_m) const {
  const FreeSpaceTolerance tolerance = Tolerance(depth_m);
  const Eigen::Vector3f p = p_world.cast<float>();
  for (auto view = views_.rbegin(); view != views_.rend(); ++view) {
    if (view->Vote(p, tolerance) == Visibility::kSeeThrough) return true;
  }
  return false;
}

DepthReference::FrameTest DepthReference::ForFrame(const Eigen::Isometry3d& T_world_camera) const {
  FrameTest test;
  test.reference_ = this;
  for (auto view = views_.rbegin(); view != views_.rend(); ++view) {
    test.T_view_camera_.push_back(
        (view->T_camera_world().cast<double>() * T_world_camera).cast<float>());
  }
  return test;
}

std::vector<uint8_t> DepthReference::FrameTest::ChangedAll(
    const std::vector<Eigen::Vector3d>& points_camera) const {
  const size_t n = points_camera.size();
  std::vector<uint8_t> changed(n, 0);
  std::vector<Eigen::Vector3f> points(n);
  std::vector<double> margins(n);
  std::vector<int> pending(n);  // indices not yet seen through
  for (size_t i = 0; i < n; ++i) {
    points[i] = points_camera[i].cast<float>();
    margins[i] = reference_->Tolerance(points_camera[i].z()).margin_m;
    pending[i] = static_cast<int>(i);
  }
  FreeSpaceTolerance tolerance = reference_->Tolerance(0.0);
  auto view = reference_->views_.rbegin();
  for (const Eigen::Isometry3f& T_view_camera : T_view_camera_) {
    size_t kept = 0;
    for (const int i : pending) {
      tolerance.margin_m = margins[i];
      if (view->VoteInView(T_view_camera * points[i], tolerance) == Visibility::kSeeThrough) {
        changed[i] = 1;
      } else {
        pending[kept++] = i;
      }
    }
    pending.resize(kept);
    ++view;
  }
  return changed;
}

void AddDepthChangeRegions(const CellGrid& grid, const DepthReference& reference,
                           const std::vector<ObservedPoint>& points,
                           const std::vector<uint8_t>& blocked,
                           const Eigen::Isometry3d& T_world_camera, const DynamicMaskConfig& config,
                           DynamicMask* mask) {
  const size_t first_new = mask->regions.size();
  const int stride = kDepthChangeStride;
  std::vector<uint8_t> changed =
      ChangedCells(grid, reference, blocked, mask->labels.ptr<uint16_t>(), T_world_camera, stride);
  for (const std::vector<int>& group :
       ChangedGroups(grid, std::move(changed), stride, config.depth_change_min_cells)) {
    RegionSeeds seeds;
    seeds.label = static_cast<uint16_t>(mask->regions.size() + 1);
    seeds.margin_m = config.margin_m;
    seeds.cells = group;
    for (int cell : group) seeds.Include(grid.CellPoint(cell));
    std::vector<uint16_t> touched;
    DynamicRegion region =
        GrowRegion(grid, seeds, T_world_camera, blocked, &mask->labels, &touched);
    if (region.cells == 0) continue;
    // The same surface as an earlier region, or a part of the same thing (a limb in front of the
    // body, the head above it): one moving thing.
    const uint16_t into = touched.empty() ? NearRegion(*mask, region, config.margin_m)
                                          : *std::min_element(touched.begin(), touched.end());
    if (into == 0) {
      mask->regions.push_back(std::move(region));
    } else {
      MergeRegion(region, &mask->regions[into - 1], &mask->labels);
    }
  }
  AttachPoints(grid, points, first_new, T_world_camera, mask);
}

}  // namespace dslam
