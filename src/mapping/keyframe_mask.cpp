#include "dslam/mapping/keyframe_mask.h"

#include <cmath>

#include <opencv2/imgproc.hpp>

namespace dslam {

cv::Mat DynamicPixelMask(const KeyFrameRecord& keyframe, const MapConfig& config) {
  return DiscMask(keyframe.points, keyframe.frame.depth_m.size(), config.mask_radius_px);
}

cv::Mat DiscMask(const std::vector<ObservedPoint>& points, cv::Size size, int radius_px) {
  cv::Mat mask(size, CV_8UC1, cv::Scalar(0));
  for (const ObservedPoint& point : points) {
    if (point.is_static) continue;
    const cv::Point centre(static_cast<int>(std::lround(point.uv_raw.x())),
                           static_cast<int>(std::lround(point.uv_raw.y())));
    cv::circle(mask, centre, radius_px, cv::Scalar(255), cv::FILLED);
  }
  return mask;
}

}  // namespace dslam
