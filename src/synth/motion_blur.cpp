// Motion blur of the synthetic colour camera: sub-frame count and averaging (motion_blur.h).
#include "dslam/synth/motion_blur.h"

#include <algorithm>
#include <cmath>

namespace dslam {
namespace synth {
namespace {

constexpr double kMinDepthInPath = 1e-3;  ///< [m] nearer (or behind) in a path pose: skipped

/// Grid coordinates 0, stride, 2 stride, ... below `size`, plus size - 1.
std::vector<int> GridCoordinates(int size, int stride) {
  std::vector<int> out;
  for (int x = 0; x < size; x += std::max(1, stride)) out.push_back(x);
  if (out.back() != size - 1) out.push_back(size - 1);
  return out;
}

}  // namespace

std::vector<Eigen::Isometry3d> ExposurePath(const CameraMotionParams& motion, double t_s,
                                            uint32_t seed, double exposure_s, int segments) {
  std::vector<Eigen::Isometry3d> path;
  for (int k = 0; k <= segments; ++k) {
    const double offset = exposure_s * (static_cast<double>(k) / segments - 0.5);
    path.push_back(CameraPoseAt(motion, t_s + offset, seed));
  }
  return path;
}

double MaxImagePathPx(const PinholeCamera& camera, const cv::Mat& depth_m,
                      const Eigen::Isometry3d& T_world_camera_ref,
                      const std::vector<Eigen::Isometry3d>& T_world_camera_path, int pixel_stride) {
  // A point seen at the reference pose as homogeneous (p, w) in the reference camera frame:
  // (depth * ray, 1) for a hit, (ray, 0) for a direction at infinity (nothing hit).
  std::vector<Eigen::Isometry3d> T_path_ref;
  for (const Eigen::Isometry3d& T : T_world_camera_path) {
    T_path_ref.push_back(T.inverse() * T_world_camera_ref);
  }
  double longest = 0.0;
  for (int v : GridCoordinates(camera.height(), pixel_stride)) {
    for (int u : GridCoordinates(camera.width(), pixel_stride)) {
      const Eigen::Vector3d ray((u - camera.cx()) / camera.fx(), (v - camera.cy()) / camera.fy(),
                                1.0);
      const double depth = depth_m.at<float>(v, u);
      const Eigen::Vector3d p = depth > 0.0 ? Eigen::Vector3d(depth * ray) : ray;
      const double w = depth > 0.0 ? 1.0 : 0.0;
      double length = 0.0;
      Eigen::Vector2d previous;
      bool valid = true;
      for (size_t k = 0; k < T_path_ref.size() && valid; ++k) {
        const Eigen::Vector3d q = T_path_ref[k].linear() * p + w * T_path_ref[k].translation();
        valid = q.z() > kMinDepthInPath * (w > 0.0 ? 1.0 : q.norm());
        const Eigen::Vector2d uv = camera.Project(q);
        if (k > 0) length += (uv - previous).norm();
        previous = uv;
      }
      if (valid) longest = std::max(longest, length);
    }
  }
  return longest;
}

int SubframeCount(double path_px, const ExposureParams& exposure) {
  const int cap = std::max(1, exposure.max_subframes - (exposure.max_subframes % 2 == 0 ? 1 : 0));
  const double needed = std::ceil(path_px / exposure.max_step_px);
  if (!(needed < cap)) return cap;  // also for NaN
  int n = std::max(1, static_cast<int>(needed));
  if (n % 2 == 0) ++n;
  return std::min(n, cap);
}

std::vector<double> SubframeOffsets(double exposure_s, int n) {
  std::vector<double> offsets;
  for (int k = 0; k < n; ++k) {
    offsets.push_back(static_cast<double>(2 * k + 1 - n) / (2.0 * n) * exposure_s);
  }
  return offsets;
}

cv::Mat MeanColour(const std::vector<cv::Mat>& images) {
  const cv::Mat& first = images.front();
  cv::Mat sum(first.size(), CV_32SC3, cv::Scalar::all(0));
  for (const cv::Mat& image : images) {
    for (int v = 0; v < image.rows; ++v) {
      const cv::Vec3b* in = image.ptr<cv::Vec3b>(v);
      cv::Vec3i* acc = sum.ptr<cv::Vec3i>(v);
      for (int u = 0; u < image.cols; ++u) {
        for (int c = 0; c < 3; ++c) acc[u][c] += in[u][c];
      }
    }
  }
  const int n = static_cast<int>(images.size());
  cv::Mat out(first.size(), CV_8UC3);
  for (int v = 0; v < out.rows; ++v) {
    const cv::Vec3i* acc = sum.ptr<cv::Vec3i>(v);
    cv::Vec3b* dst = out.ptr<cv::Vec3b>(v);
    for (int u = 0; u < out.cols; ++u) {
      for (int c = 0; c < 3; ++c) dst[u][c] = static_cast<uint8_t>((2 * acc[u][c] + n) / (2 * n));
    }
  }
  return out;
}

}  // namespace synth
}  // namespace dslam
