#include "orb_pyramid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "dslam/features/fast_grid.h"

namespace dslam {
namespace orb {
namespace {

constexpr int kFastMargin = 3;   // [px] FAST needs a radius-3 circle around each pixel
constexpr int kCellSizePx = 30;  // [px] detection grid cell side at every level (ORB-SLAM2's W)

// Share of num_features per level, proportional to 1/scale (ORB-SLAM2's split).
std::vector<int> LevelShares(const FeaturesConfig& config) {
  const double f = 1.0 / config.scale_factor;
  const int n = config.num_levels;
  std::vector<int> shares(n);
  double per_level = config.num_features * (1.0 - f) / (1.0 - std::pow(f, n));
  int total = 0;
  for (int l = 0; l + 1 < n; ++l) {
    shares[l] = static_cast<int>(std::lround(per_level));
    total += shares[l];
    per_level *= f;
  }
  shares[n - 1] = std::max(0, config.num_features - total);
  return shares;
}

bool StrongerFirst(const cv::KeyPoint& a, const cv::KeyPoint& b) { return a.response > b.response; }

// The non-empty grid cells of one level (row-major), each strongest first. FAST per cell with
// fast_threshold, and again with fast_threshold_min in the cells where it found nothing
// (FastPerCell: the keypoints of one cv::FAST call per cell, found with fewer calls).
// (Plain whole-level suppression, across cell borders, changes about 4.5 % of the keypoints, and
// the synthetic walking sequences then lose track in 3 of the 5 seeds that tracked before:
// docs/benchmarks/speed.md.)
std::vector<std::vector<cv::KeyPoint>> DetectCells(const cv::Mat& level,
                                                   const FeaturesConfig& config) {
  FastGrid grid;
  grid.x0 = grid.y0 = kEdgeThreshold;
  grid.x1 = level.cols - kEdgeThreshold;
  grid.y1 = level.rows - kEdgeThreshold;
  grid.size = kCellSizePx;
  if (grid.x1 - grid.x0 < 2 * kFastMargin || grid.y1 - grid.y0 < 2 * kFastMargin) return {};
  std::vector<std::vector<cv::KeyPoint>> found = FastPerCell(level, grid, config.fast_threshold);
  std::vector<uint8_t> empty(found.size());
  for (size_t index = 0; index < found.size(); ++index) empty[index] = found[index].empty();
  if (std::count(empty.begin(), empty.end(), 1) > 0) {
    std::vector<std::vector<cv::KeyPoint>> weak =
        FastPerCell(level, grid, config.fast_threshold_min, &empty);
    for (size_t index = 0; index < found.size(); ++index) {
      if (empty[index]) found[index] = std::move(weak[index]);
    }
  }
  std::vector<std::vector<cv::KeyPoint>> cells;
  for (std::vector<cv::KeyPoint>& cell : found) {
    if (cell.empty()) continue;
    std::sort(cell.begin(), cell.end(), StrongerFirst);
    cells.push_back(std::move(cell));
  }
  return cells;
}

// Round-robin over cells, strongest first within a round; at most `share` keypoints.
std::vector<cv::KeyPoint> Distribute(const std::vector<std::vector<cv::KeyPoint>>& cells,
                                     int share) {
  std::vector<cv::KeyPoint> kept;
  std::vector<cv::KeyPoint> candidates;
  for (size_t round = 0; static_cast<int>(kept.size()) < share; ++round) {
    candidates.clear();
    for (const auto& cell : cells) {
      if (round < cell.size()) candidates.push_back(cell[round]);
    }
    if (candidates.empty()) break;
    std::sort(candidates.begin(), candidates.end(), StrongerFirst);
    const size_t take = std::min(candidates.size(), static_cast<size_t>(share) - kept.size());
    kept.insert(kept.end(), candidates.begin(), candidates.begin() + take);
  }
  return kept;
}

// Half width of the orientation disc in row dy (|dy| <= kPatchRadius).
const std::array<int, 2 * kPatchRadius + 1>& DiscHalfWidths() {
  static const std::array<int, 2 * kPatchRadius + 1> widths = [] {
    std::array<int, 2 * kPatchRadius + 1> w{};
    for (int dy = -kPatchRadius; dy <= kPatchRadius; ++dy) {
      w[dy + kPatchRadius] = static_cast<int>(std::sqrt(kPatchRadius * kPatchRadius - dy * dy));
    }
    return w;
  }();
  return widths;
}

}  // namespace

std::vector<double> LevelScales(const FeaturesConfig& config) {
  std::vector<double> scales(config.num_levels, 1.0);
  for (int l = 1; l < config.num_levels; ++l) scales[l] = scales[l - 1] * config.scale_factor;
  return scales;
}

Pyramids BuildPyramids(const cv::Mat& grey, const FeaturesConfig& config, bool with_descriptor) {
  const std::vector<double> scales = LevelScales(config);
  const int n = config.num_levels;
  auto level_size = [&](int l) {
    return cv::Size(cvRound(grey.cols / scales[l]), cvRound(grey.rows / scales[l]));
  };
  Pyramids out;
  out.detection.resize(n);
  out.detection[0] = grey;
  if (with_descriptor) {
    out.descriptor.resize(n);
    out.descriptor[0] = grey;
  }
  // Job 0 builds the whole descriptor pyramid (its levels depend on each other; their resizes
  // take about as long as the detection levels together), job l the detection level l.
  cv::parallel_for_(cv::Range(0, n), [&](const cv::Range& range) {
    for (int job = range.start; job < range.end; ++job) {
      if (job > 0) {
        cv::resize(grey, out.detection[job], level_size(job), 0, 0, cv::INTER_LINEAR_EXACT);
        continue;
      }
      for (int l = 1; with_descriptor && l < n; ++l) {
        cv::resize(out.descriptor[l - 1], out.descriptor[l], level_size(l), 0, 0,
                   cv::INTER_LINEAR_EXACT);
      }
    }
  });
  return out;
}

std::vector<std::vector<cv::KeyPoint>> DetectLevelKeypoints(const std::vector<cv::Mat>& levels,
                                                            const FeaturesConfig& config) {
  const int num_levels = static_cast<int>(levels.size());
  std::vector<std::vector<std::vector<cv::KeyPoint>>> cells(num_levels);
  cv::parallel_for_(cv::Range(0, num_levels), [&](const cv::Range& range) {
    for (int l = range.start; l < range.end; ++l) cells[l] = DetectCells(levels[l], config);
  });
  const std::vector<int> shares = LevelShares(config);
  std::vector<std::vector<cv::KeyPoint>> kept(num_levels);
  int carry = 0;  // a level's shortfall goes to the next one
  for (int l = 0; l < num_levels; ++l) {
    const int share = shares[l] + carry;
    kept[l] = Distribute(cells[l], share);
    carry = share - static_cast<int>(kept[l].size());
  }
  cv::parallel_for_(cv::Range(0, num_levels), [&](const cv::Range& range) {
    for (int l = range.start; l < range.end; ++l) {
      for (cv::KeyPoint& kp : kept[l]) {
        kp.octave = l;
        kp.size = static_cast<float>(2 * kPatchRadius + 1);
        kp.angle = IntensityCentroidAngle(levels[l], kp.pt);
      }
    }
  });
  return kept;
}

}  // namespace orb

namespace {

// Moments m10, m01 of the disc of orb::kPatchRadius around (cx, cy), which lies inside `level`:
// the rows dy and -dy together (their sum weighs dx, their difference dy), as ORB-SLAM2 does.
void DiscMomentsInside(const cv::Mat& level, int cx, int cy, long* m10, long* m01) {
  constexpr int kRadius = orb::kPatchRadius;
  const std::array<int, 2 * kRadius + 1>& half_widths = orb::DiscHalfWidths();
  const uchar* centre = level.ptr<uchar>(cy) + cx;
  for (int dx = -kRadius; dx <= kRadius; ++dx) *m10 += dx * centre[dx];
  const size_t step = level.step1();
  for (int dy = 1; dy <= kRadius; ++dy) {
    const int half = half_widths[dy + kRadius];
    const uchar* below = centre + dy * step;
    const uchar* above = centre - dy * step;
    int row_moment = 0, row_difference = 0;
    for (int dx = -half; dx <= half; ++dx) {
      row_moment += dx * (below[dx] + above[dx]);
      row_difference += below[dx] - above[dx];
    }
    *m10 += row_moment;
    *m01 += static_cast<long>(dy) * row_difference;
  }
}

// The same moments for a disc crossing the border of `level`: each row clipped to the image.
void DiscMomentsClipped(const cv::Mat& level, int cx, int cy, long* m10, long* m01) {
  constexpr int kRadius = orb::kPatchRadius;
  const std::array<int, 2 * kRadius + 1>& half_widths = orb::DiscHalfWidths();
  for (int dy = -kRadius; dy <= kRadius; ++dy) {
    const int y = cy + dy;
    if (y < 0 || y >= level.rows) continue;
    const int half = half_widths[dy + kRadius];
    const int x0 = std::max(-half, -cx);
    const int x1 = std::min(half, level.cols - 1 - cx);
    const uchar* row = level.ptr<uchar>(y) + cx;
    int row_sum = 0, row_moment = 0;
    for (int dx = x0; dx <= x1; ++dx) {
      row_sum += row[dx];
      row_moment += dx * row[dx];
    }
    *m10 += row_moment;
    *m01 += static_cast<long>(dy) * row_sum;
  }
}

}  // namespace

float IntensityCentroidAngle(const cv::Mat& level, const cv::Point2f& pt) {
  if (level.type() != CV_8UC1) throw std::invalid_argument("IntensityCentroidAngle: not CV_8UC1");
  constexpr int kRadius = orb::kPatchRadius;
  const int cx = cvRound(pt.x), cy = cvRound(pt.y);
  const bool inside =
      cx >= kRadius && cy >= kRadius && cx + kRadius < level.cols && cy + kRadius < level.rows;
  long m01 = 0, m10 = 0;  // integer moments: exact, so both ways give the same sums
  if (inside) {
    DiscMomentsInside(level, cx, cy, &m10, &m01);
  } else {
    DiscMomentsClipped(level, cx, cy, &m10, &m01);
  }
  const float angle = static_cast<float>(
      std::atan2(static_cast<double>(m01), static_cast<double>(m10)) * 180.0 / CV_PI);
  return angle < 0.0f ? angle + 360.0f : angle;
}

}  // namespace dslam
