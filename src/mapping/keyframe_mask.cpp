#include "dslam/mapping/keyframe_mask.h"

#include <opencv2/imgproc.hpp>

#include "dslam/mapping/dynamic_mask.h"

namespace dslam {

cv::Mat DynamicPixelMask(const KeyFrameRecord& keyframe, const DynamicMaskConfig& config) {
  const DynamicMask mask =
      ComputeDynamicMask(keyframe.frame, keyframe.T_world_camera, keyframe.points, config);
  cv::Mat pixels = cv::Mat::zeros(keyframe.frame.depth_m.size(), CV_8UC1);
  if (mask.labels.empty() || mask.regions.empty()) return pixels;
  const int d = mask.decimation;
  const cv::Mat cells = mask.labels != 0;  // CV_8UC1, 255 on masked cells
  cv::resize(cells, pixels(cv::Rect(0, 0, cells.cols * d, cells.rows * d)),
             cv::Size(cells.cols * d, cells.rows * d), 0, 0, cv::INTER_NEAREST);
  return pixels;
}

}  // namespace dslam
