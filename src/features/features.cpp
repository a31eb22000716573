#include "dslam/features/features.h"

#include <algorithm>
#include <stdexcept>

#include <opencv2/core/utility.hpp>
#include <opencv2/features2d.hpp>

#include "orb_pyramid.h"

namespace dslam {
namespace {

// rBRIEF descriptors of the keypoints of every level (level pixels), one cv::ORB call per level
// on that level's image of the descriptor pyramid (Pyramids::descriptor: the images cv::ORB's own
// pyramid has, so the descriptors are the ones a multi-level cv::ORB::compute gives), levels in
// parallel; rows in the order of the levels and their keypoints.
cv::Mat LevelDescriptors(const std::vector<cv::Mat>& levels,
                         const std::vector<std::vector<cv::KeyPoint>>& keypoints,
                         const FeaturesConfig& config) {
  const int num_levels = static_cast<int>(levels.size());
  std::vector<cv::Mat> descriptors(num_levels);
  std::vector<char> intact(num_levels, 1);
  cv::parallel_for_(cv::Range(0, num_levels), [&](const cv::Range& range) {
    for (int l = range.start; l < range.end; ++l) {
      if (keypoints[l].empty()) continue;
      // A one-level cv::ORB keeps the given angles and computes rBRIEF on the blurred level.
      cv::Ptr<cv::ORB> orb = cv::ORB::create(
          static_cast<int>(keypoints[l].size()), static_cast<float>(config.scale_factor), 1,
          orb::kEdgeThreshold, 0, 2, cv::ORB::FAST_SCORE, 2 * orb::kPatchRadius + 1);
      std::vector<cv::KeyPoint> level_keypoints = keypoints[l];
      for (cv::KeyPoint& kp : level_keypoints) kp.octave = 0;
      orb->compute(levels[l], level_keypoints, descriptors[l]);
      // cv::ORB drops keypoints within its edge threshold; detection never places any there.
      intact[l] =
          level_keypoints.size() == keypoints[l].size() &&
          std::equal(level_keypoints.begin(), level_keypoints.end(), keypoints[l].begin(),
                     [](const cv::KeyPoint& a, const cv::KeyPoint& b) { return a.pt == b.pt; });
    }
  });
  if (std::count(intact.begin(), intact.end(), 0) > 0) {
    throw std::logic_error("ExtractFeatures: cv::ORB dropped or reordered keypoints");
  }
  cv::Mat all;
  std::vector<cv::Mat> non_empty;
  for (const cv::Mat& d : descriptors) {
    if (!d.empty()) non_empty.push_back(d);
  }
  if (!non_empty.empty()) cv::vconcat(non_empty, all);
  return all;
}

// The keypoints of all levels in level order, positions and sizes in level-0 pixels.
std::vector<cv::KeyPoint> ToLevelZero(const std::vector<std::vector<cv::KeyPoint>>& per_level,
                                      const std::vector<double>& scales) {
  std::vector<cv::KeyPoint> all;
  for (const std::vector<cv::KeyPoint>& level : per_level) {
    for (cv::KeyPoint kp : level) {
      kp.pt *= static_cast<float>(scales[kp.octave]);
      kp.size *= static_cast<float>(scales[kp.octave]);
      all.push_back(kp);
    }
  }
  return all;
}

// The feature of keypoint `kp` [level-0 px]: undistorted and measured in depth.
Feature MeasuredFeature(const RgbdFrame& frame, const cv::KeyPoint& kp,
                        const std::vector<double>& octave_scale,
                        const DepthNoiseConfig& depth_noise) {
  const PinholeCamera& camera = *frame.camera;
  Feature f;
  f.uv_raw = Eigen::Vector2d(kp.pt.x, kp.pt.y);
  f.uv_ideal = camera.Undistort(f.uv_raw);
  f.octave = kp.octave;
  f.angle_deg = kp.angle;
  f.response = kp.response;
  // A keypoint found at pyramid level o is localised to about scale^o pixels (ORB-SLAM2's
  // sigma^2 = scale^(2 o)), so its lateral noise grows with the level.
  DepthNoiseConfig level_noise = depth_noise;
  level_noise.pixel_sigma_px *= octave_scale[kp.octave];
  f.measurement = MeasurePoint(frame.depth_m, f.uv_raw, f.uv_ideal, camera, level_noise);
  return f;
}

}  // namespace

int FrameFeatures::NumWithDepth() const {
  return static_cast<int>(std::count_if(features.begin(), features.end(), [](const Feature& f) {
    return f.measurement.has_value();
  }));
}

std::vector<cv::KeyPoint> DetectDistributedKeypoints(const cv::Mat& grey,
                                                     const FeaturesConfig& config) {
  const std::vector<cv::Mat> levels = orb::BuildPyramids(grey, config, false).detection;
  return ToLevelZero(orb::DetectLevelKeypoints(levels, config), orb::LevelScales(config));
}

FrameFeatures ExtractFeatures(const RgbdFrame& frame, const FeaturesConfig& config,
                              const DepthNoiseConfig& depth_noise) {
  const std::string problem = frame.Check();
  if (!problem.empty()) throw std::invalid_argument("ExtractFeatures: " + problem);
  const cv::Mat grey = frame.Grey();
  const orb::Pyramids pyramids = orb::BuildPyramids(grey, config, true);
  const std::vector<std::vector<cv::KeyPoint>> keypoints =
      orb::DetectLevelKeypoints(pyramids.detection, config);
  FrameFeatures out;
  out.descriptors = LevelDescriptors(pyramids.descriptor, keypoints, config);
  out.octave_scale = orb::LevelScales(config);
  const std::vector<cv::KeyPoint> level_zero = ToLevelZero(keypoints, out.octave_scale);
  out.features.resize(level_zero.size());
  cv::parallel_for_(cv::Range(0, static_cast<int>(level_zero.size())), [&](const cv::Range& r) {
    for (int k = r.start; k < r.end; ++k) {
      out.features[k] = MeasuredFeature(frame, level_zero[k], out.octave_scale, depth_noise);
    }
  });
  return out;
}

}  // namespace dslam
