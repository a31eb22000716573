#include "dslam/mapping/free_space.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <opencv2/imgproc.hpp>

namespace dslam {

FreeSpaceTolerance FreeSpaceTolerance::From(const MapConfig& config, double min_depth_m,
                                            double max_depth_m) {
  FreeSpaceTolerance tolerance;
  tolerance.margin_m = config.free_space_margin_m;
  tolerance.margin_ratio = config.free_space_margin_ratio;
  tolerance.min_depth_m = min_depth_m;
  tolerance.max_depth_m = max_depth_m;
  return tolerance;
}

namespace {

/// Per block of `block_px` x `block_px` pixels of `depth_m` the nearest depth [m] of at least
/// `min_depth_m` (NaN and infinity: none), infinity when there is none.
cv::Mat BlockMinimum(const cv::Mat& depth_m, int block_px, double min_depth_m) {
  const float inf = std::numeric_limits<float>::infinity();
  cv::Mat blocks((depth_m.rows + block_px - 1) / block_px, (depth_m.cols + block_px - 1) / block_px,
                 CV_32FC1, cv::Scalar(inf));
  for (int v = 0; v < depth_m.rows; ++v) {
    const float* row = depth_m.ptr<float>(v);
    float* out = blocks.ptr<float>(v / block_px);
    for (int u = 0; u < depth_m.cols; ++u) {
      const float d = row[u];
      // NaN and infinity fail: no measurement.
      if (d >= min_depth_m && d < out[u / block_px]) out[u / block_px] = d;
    }
  }
  return blocks;
}

}  // namespace

DepthView::DepthView(const RgbdFrame& frame, const Eigen::Isometry3d& T_world_camera, int block_px,
                     double min_depth_m)
    : DepthView(frame.camera, T_world_camera, block_px,
                BlockMinimum(frame.depth_m, block_px, min_depth_m)) {}

DepthView::DepthView(std::shared_ptr<const PinholeCamera> camera,
                     const Eigen::Isometry3d& T_world_camera, int block_px,
                     const cv::Mat& block_depth_m)
    : camera_(std::move(camera)), distorted_(!camera_->distortion().IsZero()), block_px_(block_px) {
  for (int shift = 0; shift < 16 && block_shift_ < 0; ++shift) {
    if ((1 << shift) == block_px) block_shift_ = shift;
  }
  set_pose(T_world_camera);
  // The nearest depth of each block's 3x3 neighbourhood (a grey erosion: the minimum).
  cv::erode(block_depth_m, near_m_, cv::Mat::ones(3, 3, CV_8UC1), cv::Point(-1, -1), 1,
            cv::BORDER_CONSTANT, cv::Scalar(std::numeric_limits<float>::infinity()));
}

void DepthView::set_pose(const Eigen::Isometry3d& T_world_camera) {
  T_camera_world_ = T_world_camera.inverse().cast<float>();
}

Visibility DepthView::Vote(const Eigen::Vector3f& p_world,
                           const FreeSpaceTolerance& tolerance) const {
  return VoteInView(T_camera_world_ * p_world, tolerance);
}

Visibility DepthView::VoteInView(const Eigen::Vector3f& p,
                                 const FreeSpaceTolerance& tolerance) const {
  const double z = p.z();
  if (!tolerance.InRange(z)) return Visibility::kNoVote;
  const PinholeCamera& camera = *camera_;
  // PinholeCamera::Project, inline (the same arithmetic): this runs for many points per frame.
  Eigen::Vector2d uv(camera.fx() * p.x() / z + camera.cx(), camera.fy() * p.y() / z + camera.cy());
  if (distorted_) {
    // Far outside the image the distortion polynomial may fold a point back into it.
    const double beyond_px = -0.25 * std::max(camera.width(), camera.height());
    if (!camera.InImage(uv, beyond_px)) return Visibility::kNoVote;
    uv = camera.Distort(uv);
  }
  if (!(uv.x() >= 0.0 && uv.y() >= 0.0 && uv.x() <= camera.width() - 1 &&
        uv.y() <= camera.height() - 1)) {
    return Visibility::kNoVote;  // PinholeCamera::InImage
  }
  // uv >= 0 here: a shift divides as / does (an integer division is slow; blocks are usually
  // a power of two pixels wide).
  const int iu = static_cast<int>(uv.x()), iv = static_cast<int>(uv.y());
  const int bu = block_shift_ >= 0 ? iu >> block_shift_ : iu / block_px_;
  const int bv = block_shift_ >= 0 ? iv >> block_shift_ : iv / block_px_;
  if (bu < 0 || bv < 0 || bu >= near_m_.cols || bv >= near_m_.rows) return Visibility::kNoVote;
  const float near = near_m_.at<float>(bv, bu);
  if (std::isinf(near)) return Visibility::kNoVote;
  const double margin = tolerance.Margin(z);
  if (near > z + margin) return Visibility::kSeeThrough;
  if (near >= z - margin) return Visibility::kSupport;
  return Visibility::kNoVote;  // something nearer occludes the point
}

}  // namespace dslam
