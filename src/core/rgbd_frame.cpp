#include "dslam/core/rgbd_frame.h"

#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>

namespace dslam {
namespace {

std::string SizeText(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

std::string RgbdFrame::Check() const {
  if (!std::isfinite(stamp_s)) return "frame stamp is not finite";
  if (!camera) return "frame has no camera model";
  if (colour.empty()) return "frame has no colour image";
  if (colour.type() != CV_8UC3 && colour.type() != CV_8UC1) {
    return "colour image must be 8-bit BGR or grey (CV_8UC3 or CV_8UC1), got OpenCV type " +
           std::to_string(colour.type());
  }
  if (depth_m.empty()) return "frame has no depth image";
  if (depth_m.type() != CV_32FC1) {
    return "depth image must be CV_32FC1 metres, got OpenCV type " + std::to_string(depth_m.type());
  }
  const std::string colour_size = SizeText(colour.cols, colour.rows);
  if (depth_m.size() != colour.size()) {
    return "depth image " + SizeText(depth_m.cols, depth_m.rows) +
           " differs from the colour image " + colour_size +
           " (depth must be registered to colour at the same size)";
  }
  if (camera->width() != colour.cols || camera->height() != colour.rows) {
    return "camera " + SizeText(camera->width(), camera->height()) +
           " differs from the colour image " + colour_size;
  }
  return "";
}

cv::Mat RgbdFrame::Grey() const {
  if (colour.channels() == 1) return colour;
  cv::Mat grey;
  cv::cvtColor(colour, grey, cv::COLOR_BGR2GRAY);
  return grey;
}

}  // namespace dslam
