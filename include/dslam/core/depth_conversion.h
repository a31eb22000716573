#pragma once
// Conversions of sensor depth encodings to the core's CV_32FC1 metres (0 = no measurement).

#include <opencv2/core.hpp>

namespace dslam {

/// Range of the units per metre of 16-bit depth [1/m]: 1 (a unit of one metre) to 1e6 (a unit of
/// one micrometre). Within it every 16-bit value maps to a finite, nonzero float depth.
constexpr double kMinDepthUnitsPerMetre = 1.0;
constexpr double kMaxDepthUnitsPerMetre = 1e6;

/// 16UC1 depth in integer units where `units_per_metre` units are one metre (1000 for OpenNI
/// millimetres, 5000 for TUM/Bonn PNG files) -> CV_32FC1 metres; 0 stays 0 (no measurement).
/// Throws std::invalid_argument on another type, an empty image or a scale outside
/// [kMinDepthUnitsPerMetre, kMaxDepthUnitsPerMetre].
cv::Mat DepthFromScaledUint16(const cv::Mat& depth_units, double units_per_metre);

/// 16UC1 millimetres (ROS 16UC1 convention) -> CV_32FC1 metres.
inline cv::Mat DepthFromMillimetres(const cv::Mat& depth_mm) {
  return DepthFromScaledUint16(depth_mm, 1000.0);
}

/// 32FC1 metres (ROS 32FC1 convention) -> CV_32FC1 metres with NaN, infinite, negative and zero
/// values replaced by 0 (no measurement). Throws std::invalid_argument on another type or an
/// empty image.
cv::Mat DepthFromMetres(const cv::Mat& depth_m);

/// Reads a 16-bit depth PNG (TUM layout) and converts it with `units_per_metre` (5000 for TUM).
/// Throws std::runtime_error when the file cannot be read, is not 16-bit single channel, or is
/// not a PNG within dslam/core/image_limits.h (CheckImageFile, before decoding).
cv::Mat ReadDepthPng(const std::string& path, double units_per_metre);

/// Number of pixels with a valid depth (finite and > 0).
int CountValidDepth(const cv::Mat& depth_m);

}  // namespace dslam
