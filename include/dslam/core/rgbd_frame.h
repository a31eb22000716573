#pragma once
// One synchronized colour + depth capture, the input unit of the odometry.

#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "dslam/core/camera.h"

namespace dslam {

/// Colour and registered depth of one instant, with the camera that took them.
struct RgbdFrame {
  double stamp_s = 0.0;  ///< [s] capture time of the colour image (seconds since epoch or bag)
  cv::Mat colour;        ///< CV_8UC3 BGR or CV_8UC1 grey, width x height of `camera`
  cv::Mat depth_m;       ///< CV_32FC1 depth along the optical axis [m]; 0 = no measurement
  std::shared_ptr<const PinholeCamera> camera;  ///< intrinsics of the colour camera

  /// Checks types and sizes; returns an empty string when valid, else what is wrong.
  std::string Check() const;
};

}  // namespace dslam
