#include "dslam/core/rgbd_frame.h"

#include <string>

namespace dslam {

std::string RgbdFrame::Check() const {
  if (!camera) return "frame has no camera model";
  if (colour.empty()) return "frame has no colour image";
  if (colour.type() != CV_8UC3 && colour.type() != CV_8UC1) {
    return "colour image must be 8-bit BGR or grey";
  }
  if (depth_m.type() != CV_32FC1) return "depth image must be CV_32FC1 metres";
  const cv::Size expected(camera->width(), camera->height());
  if (colour.size() != expected || depth_m.size() != expected) {
    return "image size mismatch: colour " + std::to_string(colour.cols) + "x" +
           std::to_string(colour.rows) + ", depth " + std::to_string(depth_m.cols) + "x" +
           std::to_string(depth_m.rows) + ", camera " + std::to_string(expected.width) + "x" +
           std::to_string(expected.height);
  }
  return "";
}

}  // namespace dslam
