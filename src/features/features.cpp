#include "dslam/features/features.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/core/utility.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

namespace dslam {
namespace {

constexpr int kEdgeThreshold = 19;  // [px] border kept free at each level (ORB patch 31 + blur)
constexpr int kFastMargin = 3;      // [px] FAST needs a radius-3 circle around each pixel
constexpr int kPatchRadius = 15;    // [px] ORB orientation / descriptor patch radius

std::vector<double> LevelScales(const FeaturesConfig& config) {
  std::vector<double> scales(config.num_levels, 1.0);
  for (int l = 1; l < config.num_levels; ++l) scales[l] = scales[l - 1] * config.scale_factor;
  return scales;
}

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

// FAST in each cell of the cell row starting at y `cy` (threshold fallback in empty cells); one
// vector per non-empty cell, strongest first.
std::vector<std::vector<cv::KeyPoint>> DetectCellRow(const cv::Mat& level, int cy,
                                                     const FeaturesConfig& config) {
  const int x0 = kEdgeThreshold, x1 = level.cols - kEdgeThreshold;
  const int y1 = level.rows - kEdgeThreshold;
  const int size = config.cell_size_px;
  std::vector<std::vector<cv::KeyPoint>> cells;
  for (int cx = x0; cx < x1; cx += size) {
    const int w = std::min(size, x1 - cx), h = std::min(size, y1 - cy);
    const cv::Rect roi(cx - kFastMargin, cy - kFastMargin, w + 2 * kFastMargin,
                       h + 2 * kFastMargin);
    std::vector<cv::KeyPoint> found;
    cv::FAST(level(roi), found, config.fast_threshold, true);
    if (found.empty()) cv::FAST(level(roi), found, config.fast_threshold_min, true);
    for (cv::KeyPoint& kp : found) kp.pt += cv::Point2f(roi.x, roi.y);
    std::sort(found.begin(), found.end(),
              [](const cv::KeyPoint& a, const cv::KeyPoint& b) { return a.response > b.response; });
    if (!found.empty()) cells.push_back(std::move(found));
  }
  return cells;
}

// One unit of detection work: a cell row of one pyramid level.
struct CellRowJob {
  int level = 0;
  int cy = 0;  ///< [px] top of the cell row at that level
};

std::vector<CellRowJob> CellRowJobs(const std::vector<cv::Mat>& levels,
                                    const FeaturesConfig& config) {
  std::vector<CellRowJob> jobs;
  for (int l = 0; l < static_cast<int>(levels.size()); ++l) {
    const int x1 = levels[l].cols - kEdgeThreshold, y1 = levels[l].rows - kEdgeThreshold;
    if (x1 - kEdgeThreshold < 2 * kFastMargin || y1 - kEdgeThreshold < 2 * kFastMargin) continue;
    for (int cy = kEdgeThreshold; cy < y1; cy += config.cell_size_px) jobs.push_back({l, cy});
  }
  return jobs;
}

// Round-robin over cells, strongest first within a round; at most `share` keypoints.
std::vector<cv::KeyPoint> Distribute(const std::vector<std::vector<cv::KeyPoint>>& cells,
                                     int share) {
  std::vector<cv::KeyPoint> kept;
  for (size_t round = 0; static_cast<int>(kept.size()) < share; ++round) {
    std::vector<cv::KeyPoint> candidates;
    for (const auto& cell : cells) {
      if (round < cell.size()) candidates.push_back(cell[round]);
    }
    if (candidates.empty()) break;
    std::sort(candidates.begin(), candidates.end(),
              [](const cv::KeyPoint& a, const cv::KeyPoint& b) { return a.response > b.response; });
    const size_t take = std::min(candidates.size(), static_cast<size_t>(share) - kept.size());
    kept.insert(kept.end(), candidates.begin(), candidates.begin() + take);
  }
  return kept;
}

// Intensity-centroid orientation [deg] over a disc of radius kPatchRadius.
float IntensityCentroidAngle(const cv::Mat& level, const cv::Point2f& pt) {
  const int cx = cvRound(pt.x), cy = cvRound(pt.y);
  double m01 = 0.0, m10 = 0.0;
  for (int dy = -kPatchRadius; dy <= kPatchRadius; ++dy) {
    const int y = cy + dy;
    if (y < 0 || y >= level.rows) continue;
    const int half = static_cast<int>(std::sqrt(kPatchRadius * kPatchRadius - dy * dy));
    const uchar* row = level.ptr<uchar>(y);
    for (int dx = -half; dx <= half; ++dx) {
      const int x = cx + dx;
      if (x < 0 || x >= level.cols) continue;
      m10 += dx * row[x];
      m01 += dy * row[x];
    }
  }
  float angle = static_cast<float>(std::atan2(m01, m10) * 180.0 / CV_PI);
  return angle < 0.0f ? angle + 360.0f : angle;
}

cv::Mat ToGrey(const cv::Mat& colour) {
  if (colour.channels() == 1) return colour;
  cv::Mat grey;
  cv::cvtColor(colour, grey, cv::COLOR_BGR2GRAY);
  return grey;
}

}  // namespace

int FrameFeatures::NumWithDepth() const {
  return static_cast<int>(std::count_if(features.begin(), features.end(), [](const Feature& f) {
    return f.measurement.has_value();
  }));
}

std::vector<cv::KeyPoint> DetectDistributedKeypoints(const cv::Mat& grey,
                                                     const FeaturesConfig& config) {
  const std::vector<double> scales = LevelScales(config);
  const std::vector<int> shares = LevelShares(config);
  std::vector<cv::Mat> levels(config.num_levels);
  cv::parallel_for_(cv::Range(0, config.num_levels), [&](const cv::Range& range) {
    for (int l = range.start; l < range.end; ++l) {
      const cv::Size size(cvRound(grey.cols / scales[l]), cvRound(grey.rows / scales[l]));
      if (l == 0)
        levels[l] = grey;
      else
        cv::resize(grey, levels[l], size, 0, 0, cv::INTER_LINEAR_EXACT);
    }
  });
  // FAST per cell row of every level, in parallel; results are stored by job, so the keypoints
  // (and their order) do not depend on the number of threads.
  const std::vector<CellRowJob> jobs = CellRowJobs(levels, config);
  std::vector<std::vector<std::vector<cv::KeyPoint>>> rows(jobs.size());
  cv::parallel_for_(cv::Range(0, static_cast<int>(jobs.size())), [&](const cv::Range& range) {
    for (int j = range.start; j < range.end; ++j) {
      rows[j] = DetectCellRow(levels[jobs[j].level], jobs[j].cy, config);
    }
  });
  std::vector<cv::KeyPoint> all;
  int carry = 0;
  size_t job = 0;
  for (int l = 0; l < config.num_levels; ++l) {
    std::vector<std::vector<cv::KeyPoint>> cells;
    for (; job < jobs.size() && jobs[job].level == l; ++job) {
      for (auto& cell : rows[job]) cells.push_back(std::move(cell));
    }
    const int share = shares[l] + carry;
    std::vector<cv::KeyPoint> kept = Distribute(cells, share);
    carry = share - static_cast<int>(kept.size());
    const size_t first = all.size();
    for (cv::KeyPoint& kp : kept) {
      kp.octave = l;
      kp.size = static_cast<float>(2 * kPatchRadius + 1) * static_cast<float>(scales[l]);
      all.push_back(kp);
    }
    cv::parallel_for_(cv::Range(static_cast<int>(first), static_cast<int>(all.size())),
                      [&](const cv::Range& range) {
                        for (int k = range.start; k < range.end; ++k) {
                          all[k].angle = IntensityCentroidAngle(levels[l], all[k].pt);
                          all[k].pt *= static_cast<float>(scales[l]);
                        }
                      });
  }
  return all;
}

FrameFeatures ExtractFeatures(const RgbdFrame& frame, const FeaturesConfig& config,
                              const DepthNoiseConfig& depth_noise) {
  const std::string problem = frame.Check();
  if (!problem.empty()) throw std::invalid_argument("ExtractFeatures: " + problem);
  const cv::Mat grey = ToGrey(frame.colour);
  std::vector<cv::KeyPoint> keypoints = DetectDistributedKeypoints(grey, config);
  // cv::ORB keeps the provided angles and octaves and computes rBRIEF on its own pyramid (same
  // scale factor and level count); it regroups keypoints by octave, so read them back afterwards.
  cv::Ptr<cv::ORB> orb = cv::ORB::create(
      config.num_features, static_cast<float>(config.scale_factor), config.num_levels,
      kEdgeThreshold, 0, 2, cv::ORB::FAST_SCORE, 2 * kPatchRadius + 1);
  FrameFeatures out;
  orb->compute(grey, keypoints, out.descriptors);
  out.octave_scale = LevelScales(config);
  const PinholeCamera& camera = *frame.camera;
  out.features.reserve(keypoints.size());
  for (const cv::KeyPoint& kp : keypoints) {
    Feature f;
    f.uv_raw = Eigen::Vector2d(kp.pt.x, kp.pt.y);
    f.uv_ideal = camera.Undistort(f.uv_raw);
    f.octave = kp.octave;
    f.angle_deg = kp.angle;
    f.response = kp.response;
    // A keypoint found at pyramid level o is localised to about scale^o pixels (ORB-SLAM2's
    // sigma^2 = scale^(2 o)), so its lateral noise grows with the level.
    DepthNoiseConfig level_noise = depth_noise;
    level_noise.pixel_sigma_px *= out.octave_scale[kp.octave];
    f.measurement = MeasurePoint(frame.depth_m, f.uv_raw, f.uv_ideal, camera, level_noise);
    out.features.push_back(std::move(f));
  }
  return out;
}

}  // namespace dslam
