// A keyframe as a coloured cloud in its optical frame: its dynamic mask and back-projection.
#include "dslam/mapping/coloured_cloud.h"

#include <algorithm>
#include <memory>

#include <pcl/filters/voxel_grid.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <opencv2/imgproc.hpp>

#include "dslam/mapping/dynamic_mask.h"

namespace dslam {
namespace {

// Colour of pixel (u, v) as PCL's point colour.
pcl::PointXYZRGB ColourAt(const cv::Mat& colour, int u, int v) {
  if (colour.channels() == 1) {
    const uint8_t grey = colour.at<uint8_t>(v, u);
    return pcl::PointXYZRGB(grey, grey, grey);
  }
  const cv::Vec3b& bgr = colour.at<cv::Vec3b>(v, u);
  return pcl::PointXYZRGB(bgr[2], bgr[1], bgr[0]);
}

}  // namespace

ColouredCloud BackProjectKeyFrame(const RgbdFrame& frame, const cv::Mat& mask,
                                  const BackProjection& options) {
  const PinholeCamera& camera = *frame.camera;
  const auto sampled = std::make_shared<pcl::PointCloud<pcl::PointXYZRGB>>();
  const int step = std::max(1, options.pixel_step);
  for (int v = step / 2; v < frame.depth_m.rows; v += step) {
    for (int u = step / 2; u < frame.depth_m.cols; u += step) {
      const float d = frame.depth_m.at<float>(v, u);
      if (!(d >= options.min_depth_m && d <= options.max_depth_m)) continue;  // NaN too
      if (!mask.empty() && mask.at<uint8_t>(v, u) != 0) continue;
      const Eigen::Vector3d p = camera.BackProject(camera.Undistort(Eigen::Vector2d(u, v)), d);
      pcl::PointXYZRGB point = ColourAt(frame.colour, u, v);
      point.x = static_cast<float>(p.x());
      point.y = static_cast<float>(p.y());
      point.z = static_cast<float>(p.z());
      sampled->push_back(point);
    }
  }
  pcl::PointCloud<pcl::PointXYZRGB> filtered;
  if (options.voxel_size_m > 0.0 && !sampled->empty()) {
    pcl::VoxelGrid<pcl::PointXYZRGB> grid;
    const float leaf = static_cast<float>(options.voxel_size_m);
    grid.setLeafSize(leaf, leaf, leaf);
    grid.setInputCloud(sampled);
    grid.filter(filtered);
  } else {
    filtered = *sampled;
  }
  ColouredCloud cloud;
  cloud.reserve(filtered.size());
  for (const pcl::PointXYZRGB& q : filtered) {
    cloud.push_back({Eigen::Vector3f(q.x, q.y, q.z), q.r, q.g, q.b});
  }
  return cloud;
}

cv::Mat PixelMask(const DynamicMask& mask, const cv::Size& image_size) {
  cv::Mat pixels = cv::Mat::zeros(image_size, CV_8UC1);
  if (mask.labels.empty() || mask.regions.empty()) return pixels;
  const int d = mask.decimation;
  const cv::Mat cells = mask.labels != 0;  // CV_8UC1, 255 on masked cells
  cv::resize(cells, pixels(cv::Rect(0, 0, cells.cols * d, cells.rows * d)),
             cv::Size(cells.cols * d, cells.rows * d), 0, 0, cv::INTER_NEAREST);
  return pixels;
}

cv::Mat DynamicPixelMask(const KeyFrameRecord& keyframe, const DynamicMaskConfig& config) {
  const DynamicMask mask =
      ComputeDynamicMask(keyframe.frame, keyframe.T_world_camera, keyframe.points, config);
  return PixelMask(mask, keyframe.frame.depth_m.size());
}

ColouredCloud BackProjectMasked(const RgbdFrame& frame, const DynamicMask& mask,
                                const BackProjection& options) {
  cv::Mat outside;  // 255 off the mask: BackProjectKeyFrame leaves those pixels out
  cv::bitwise_not(PixelMask(mask, frame.depth_m.size()), outside);
  return BackProjectKeyFrame(frame, outside, options);
}

}  // namespace dslam
