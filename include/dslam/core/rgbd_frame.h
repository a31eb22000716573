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
  /// CV_32FC1 depth along the optical axis [m], registered to `colour` (same size and pixels);
  /// 0 = no measurement. NaN, infinite and negative values are read as no measurement too
  /// (MixDepth in depth_uncertainty.h), so a frame without any valid depth is valid input: the
  /// odometry reports it lost ("too few features with depth ...").
  cv::Mat depth_m;
  std::shared_ptr<const PinholeCamera> camera;  ///< intrinsics of the colour camera

  /// Checks the stamp (finite), image types and sizes (colour, depth and camera the same);
  /// returns an empty string when valid, else what is wrong, naming the images and their sizes,
  /// e.g. "depth image 320x240 differs from the colour image 640x480". Pixel values are not
  /// checked: black, saturated or textureless colour and missing depth are valid input.
  std::string Check() const;

  /// The colour image as 8-bit grey (CV_8UC1): converted from BGR, or `colour` itself when it is
  /// grey already (shared, not copied).
  cv::Mat Grey() const;
};

}  // namespace dslam
