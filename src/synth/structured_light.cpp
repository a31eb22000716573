#include "dslam/synth/structured_light.h"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "sensor_noise.h"

namespace dslam {
namespace synth {
namespace {

constexpr uint64_t kFixedFieldSalt = 0x2545f4914f6cdd1dull;
constexpr uint64_t kFrameFieldSalt = 0x9fb21c651e98df25ull;
constexpr uint64_t kBleedSalt = 0xc2b2ae3d27d4eb4full;
constexpr uint64_t kPixelSalt = 0x165667b19e3779f9ull;

}  // namespace

SmoothField::SmoothField(int width, int height, double cell_px, uint64_t key)
    : cell_px_(cell_px),
      grid_(static_cast<int>(height / cell_px) + 2, static_cast<int>(width / cell_px) + 2,
            CV_64FC1) {
  for (int r = 0; r < grid_.rows; ++r) {
    for (int c = 0; c < grid_.cols; ++c) {
      grid_.at<double>(r, c) =
          1.5 * Gaussian(key ^ Mix64(static_cast<uint64_t>(r) * grid_.cols + c));
    }
  }
}

double SmoothField::At(int u, int v) const {
  const double x = u / cell_px_, y = v / cell_px_;
  const int c = static_cast<int>(x), r = static_cast<int>(y);
  const double tx = x - c, ty = y - r;
  const double top = (1.0 - tx) * grid_.at<double>(r, c) + tx * grid_.at<double>(r, c + 1);
  const double bottom =
      (1.0 - tx) * grid_.at<double>(r + 1, c) + tx * grid_.at<double>(r + 1, c + 1);
  return (1.0 - ty) * top + ty * bottom;
}

StructuredLightFrame::StructuredLightFrame(const SensorParams& sensor, uint32_t seed,
                                           uint64_t frame_key, const cv::Mat& depth_true_m)
    : params_(sensor.structured_light),
      focal_baseline_px_m_(sensor.fx * sensor.structured_light.baseline_m),
      edge_jump_m_(sensor.edge_jump_m),
      fixed_(depth_true_m.cols, depth_true_m.rows, params_.field_cell_px,
             Mix64(static_cast<uint64_t>(seed) ^ kFixedFieldSalt)),
      frame_(depth_true_m.cols, depth_true_m.rows, params_.field_cell_px,
             Mix64(frame_key ^ kFrameFieldSalt)) {
  if (params_.bleed_px > 0) {
    const int size = 2 * params_.bleed_px + 1;
    cv::erode(depth_true_m, nearest_m_, cv::getStructuringElement(cv::MORPH_RECT, {size, size}));
  }
}

double StructuredLightFrame::Depth(int u, int v, double depth_m, uint64_t key) const {
  double depth = depth_m;
  if (!nearest_m_.empty()) {
    const double nearest = nearest_m_.at<float>(v, u);
    if (nearest > 0.0 && depth - nearest > edge_jump_m_ &&
        Unit(Mix64(key ^ kBleedSalt)) < params_.bleed_probability) {
      depth = nearest;
    }
  }
  double disparity = focal_baseline_px_m_ / depth + params_.fixed_sigma_px * fixed_.At(u, v) +
                     params_.frame_sigma_px * frame_.At(u, v) +
                     params_.pixel_sigma_px * Gaussian(key ^ kPixelSalt);
  if (params_.disparity_step_px > 0.0) {
    disparity = std::round(disparity / params_.disparity_step_px) * params_.disparity_step_px;
  }
  return disparity > 0.0 ? focal_baseline_px_m_ / disparity : 0.0;
}

}  // namespace synth
}  // namespace dslam
