#pragma once
// Test inputs shared by the features and tracking tests: a textured image with known depth.

#include <memory>
#include <random>

#include <opencv2/imgproc.hpp>

#include "dslam/core/rgbd_frame.h"

namespace dslam {
namespace test {

/// 640x480 camera without distortion.
inline PinholeCamera TestCamera() { return PinholeCamera(640, 480, 525.0, 525.0, 319.5, 239.5); }

/// Random grey blocks (8x8 px, seeded) slightly blurred: corners everywhere. Depth is `depth_m`
/// everywhere, or for seed 2 a slanted plane depth_m + 0.001 * u [m].
inline RgbdFrame TexturedFrame(const PinholeCamera& camera, unsigned seed, double depth_m) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> grey(0, 255);
  cv::Mat small(camera.height() / 8 + 1, camera.width() / 8 + 1, CV_8UC1);
  for (int r = 0; r < small.rows; ++r) {
    for (int c = 0; c < small.cols; ++c) small.at<uchar>(r, c) = static_cast<uchar>(grey(rng));
  }
  cv::Mat big;
  cv::resize(small, big, cv::Size(small.cols * 8, small.rows * 8), 0, 0, cv::INTER_NEAREST);
  RgbdFrame frame;
  cv::GaussianBlur(big(cv::Rect(0, 0, camera.width(), camera.height())), frame.colour,
                   cv::Size(3, 3), 0.8);
  frame.depth_m = cv::Mat(camera.height(), camera.width(), CV_32FC1, cv::Scalar(depth_m));
  if (seed == 2) {
    for (int r = 0; r < camera.height(); ++r) {
      for (int c = 0; c < camera.width(); ++c) {
        frame.depth_m.at<float>(r, c) = static_cast<float>(depth_m + 0.001 * c);
      }
    }
  }
  frame.camera = std::make_shared<PinholeCamera>(camera);
  return frame;
}

}  // namespace test
}  // namespace dslam
