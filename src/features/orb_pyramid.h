#pragma once
// Internal to the features part: the image pyramids, FAST detection spread over grid cells (the
// rule is described at the top of dslam/features/features.h).

#include <vector>

#include <opencv2/core.hpp>

#include "dslam/core/features_config.h"
#include "dslam/features/features.h"

namespace dslam {
namespace orb {

constexpr int kEdgeThreshold = 19;  ///< [px] border kept free at each level (ORB patch 31 + blur)
constexpr int kPatchRadius = 15;    ///< [px] ORB orientation / descriptor patch radius

/// [-] scale_factor^l for every level l.
std::vector<double> LevelScales(const FeaturesConfig& config);

/// The two pyramids of `grey` (level 0 of both shares its pixels).
struct Pyramids {
  /// Detection: level l is `grey` resized by 1 / scale_factor^l in one bilinear step.
  std::vector<cv::Mat> detection;
  /// Descriptors: level l is level l - 1 resized by 1 / scale_factor (bilinear), as cv::ORB
  /// builds its own. One large bilinear step aliases the small levels; rBRIEF on such levels
  /// matched worse (the synthetic walking sequences lost track in 3 of 5 seeds). Empty unless
  /// asked for.
  std::vector<cv::Mat> descriptor;
};

/// Both pyramids (the descriptor one only `with_descriptor`), built in parallel.
Pyramids BuildPyramids(const cv::Mat& grey, const FeaturesConfig& config, bool with_descriptor);

/// Keypoints of every level, in that level's pixel coordinates, with octave (= level), response
/// (FAST score), size (31 px) and angle [deg] set; distributed by the grid rule. The result does
/// not depend on OpenCV's thread count.
std::vector<std::vector<cv::KeyPoint>> DetectLevelKeypoints(const std::vector<cv::Mat>& levels,
                                                            const FeaturesConfig& config);

}  // namespace orb
}  // namespace dslam
