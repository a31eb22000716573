#pragma once
// ORB features spread evenly over the image, with undistorted positions and RGB-D measurements.
//
// Distribution rule: an image pyramid of `num_levels` levels (each `scale_factor` smaller) gets a
// share of `num_features` proportional to its area (ORB-SLAM2's geometric split, any shortfall
// carried to the next level). Every level is cut into square cells of 30 px (kCellSizePx,
// orb_pyramid.cpp); FAST runs per cell with `fast_threshold`, and again with `fast_threshold_min`
// in cells where nothing was found (the keypoints of one cv::FAST call per cell, found with one
// call per row of cells: fast_grid.h). Cells then hand out keypoints round-robin, strongest (FAST
// score) first: round k takes the k-th best keypoint of every cell that still has one, until the
// level's share is reached (the last round prefers the strongest). Orientation is the intensity
// centroid; rBRIEF descriptors come from cv::ORB run on each level of a pyramid built like
// cv::ORB's own (each level from the one before). Levels, cells' orientations, descriptors and
// depth measurements run in parallel (OpenCV's thread pool); the result does not depend on the
// thread count.

#include <optional>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "dslam/core/depth_uncertainty.h"
#include "dslam/core/features_config.h"
#include "dslam/core/rgbd_frame.h"

namespace dslam {

/// One ORB keypoint of a frame.
struct Feature {
  Eigen::Vector2d uv_raw;    ///< [px] detected position in the (distorted) colour image, level 0
  Eigen::Vector2d uv_ideal;  ///< [px] undistorted position (camera.Undistort(uv_raw))
  int octave = 0;            ///< pyramid level it was detected at (scale = scale_factor^octave)
  float angle_deg = 0.0f;    ///< [deg] ORB orientation in the image, [0, 360)
  float response = 0.0f;     ///< FAST score (larger = stronger corner)
  std::optional<PointMeasurement> measurement;  ///< y and C from depth (MeasurePoint), if any
};

/// All features of one frame; descriptors.row(i) belongs to features[i].
struct FrameFeatures {
  std::vector<Feature> features;
  cv::Mat descriptors;               ///< CV_8UC1, one 32-byte ORB descriptor per row
  std::vector<double> octave_scale;  ///< [-] scale_factor^octave for every pyramid level

  /// Number of features with a depth measurement.
  int NumWithDepth() const;
};

/// Extracts ORB features from `frame` (colour BGR or grey, depth in metres) as described at the
/// top of this file, undistorts them with frame.camera and measures each in depth (MeasurePoint at
/// the raw pixel, back-projected from the ideal one). Throws std::invalid_argument when
/// frame.Check() fails.
FrameFeatures ExtractFeatures(const RgbdFrame& frame, const FeaturesConfig& config,
                              const DepthNoiseConfig& depth_noise);

/// Keypoints [level-0 px, with octave and response] of a grey image, distributed by the rule at
/// the top of this file; orientation and descriptors not yet computed. Exposed for tests/tools.
std::vector<cv::KeyPoint> DetectDistributedKeypoints(const cv::Mat& grey,
                                                     const FeaturesConfig& config);

/// ORB orientation [deg, 0-360) at `pt` [px] of a grey (CV_8UC1, else std::invalid_argument)
/// image: the direction from `pt` to the
/// intensity centroid of the disc of radius 15 px around it (Rublee et al. 2011); pixels outside
/// the image are left out. Exposed for tests.
float IntensityCentroidAngle(const cv::Mat& grey, const cv::Point2f& pt);

}  // namespace dslam
