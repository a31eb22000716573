#include "dslam/core/depth_conversion.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "dslam/core/image_limits.h"

namespace dslam {

cv::Mat DepthFromScaledUint16(const cv::Mat& depth_units, double units_per_metre) {
  if (depth_units.type() != CV_16UC1) {
    throw std::invalid_argument("depth: expected 16UC1, got OpenCV type " +
                                std::to_string(depth_units.type()));
  }
  if (depth_units.empty()) throw std::invalid_argument("depth: the image is empty");
  if (!(units_per_metre >= kMinDepthUnitsPerMetre && units_per_metre <= kMaxDepthUnitsPerMetre)) {
    throw std::invalid_argument("depth: units per metre must be in [1, 1e6], got " +
                                std::to_string(units_per_metre));
  }
  cv::Mat metres;
  depth_units.convertTo(metres, CV_32FC1, 1.0 / units_per_metre);
  return metres;
}

cv::Mat DepthFromMetres(const cv::Mat& depth_m) {
  if (depth_m.type() != CV_32FC1) {
    throw std::invalid_argument("depth: expected 32FC1, got OpenCV type " +
                                std::to_string(depth_m.type()));
  }
  if (depth_m.empty()) throw std::invalid_argument("depth: the image is empty");
  cv::Mat clean = depth_m.clone();
  clean.forEach<float>([](float& d, const int*) {
    if (!std::isfinite(d) || d <= 0.0f) d = 0.0f;
  });
  return clean;
}

cv::Mat ReadDepthPng(const std::string& path, double units_per_metre) {
  CheckImageFile(path, /*allow_jpeg=*/false);
  const cv::Mat raw = cv::imread(path, cv::IMREAD_ANYDEPTH);
  if (raw.empty()) throw std::runtime_error("cannot read depth image " + path);
  if (raw.type() != CV_16UC1) throw std::runtime_error(path + ": depth PNG is not 16-bit");
  return DepthFromScaledUint16(raw, units_per_metre);
}

int CountValidDepth(const cv::Mat& depth_m) {
  // NaN compares false; +inf is excluded by the upper bound.
  return cv::countNonZero((depth_m > 0.0f) & (depth_m < std::numeric_limits<float>::infinity()));
}

}  // namespace dslam
