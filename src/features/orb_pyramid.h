#pragma once
// Internal to the features part: the image pyramid, FAST detection spread over grid cells and the
// intensity-centroid orientation (the rule is described at the top of dslam/features/features.h).

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

/// Level l is `grey` resized by 1 / scale_factor^l (level 0 shares `grey`'s pixels).
std::vector<cv::Mat> BuildPyramid(const cv::Mat& grey, const FeaturesConfig& config);

/// Keypoints of every level, in that level's pixel coordinates, with octave (= level), response
/// (FAST score), size (31 px) and angle [deg] set; distributed by the grid rule. The result does
/// not depend on OpenCV's thread count.
std::vector<std::vector<cv::KeyPoint>> DetectLevelKeypoints(const std::vector<cv::Mat>& levels,
                                                            const FeaturesConfig& config);

}  // namespace orb
}  // namespace dslam
