#pragma once
// Depth of a structured-light camera (scenario.h: StructuredLightParams), for ApplySensorModel.

#include <cstdint>

#include <opencv2/core.hpp>

#include "dslam/synth/scenario.h"

namespace dslam {
namespace synth {

/// A smooth random field over the image with unit variance on average: independent standard
/// normal values on a grid every `cell_px` pixels, interpolated bilinearly between them and scaled
/// by 3/2 (bilinear interpolation keeps 4/9 of the variance on average over a cell).
class SmoothField {
 public:
  SmoothField(int width, int height, double cell_px, uint64_t key);
  /// The field's value at pixel (u, v).
  double At(int u, int v) const;

 private:
  double cell_px_;
  cv::Mat grid_;  ///< CV_64FC1, (height / cell + 2) x (width / cell + 2)
};

/// One frame's structured-light depth: the disparity error fields (one fixed to the sensor, one
/// new this frame) and, for the edge bleeding, the nearest true depth around each pixel.
class StructuredLightFrame {
 public:
  /// `seed`: the sequence's (the fixed field); `frame_key`: this frame's; depth_true_m: CV_32FC1.
  StructuredLightFrame(const SensorParams& sensor, uint32_t seed, uint64_t frame_key,
                       const cv::Mat& depth_true_m);

  /// The depth [m] measured at pixel (u, v) whose true depth is `depth_m`, with the pixel's noise
  /// key; 0 when the perturbed disparity is not positive. The nearer surface within bleed_px
  /// replaces the true depth with probability bleed_probability (where it is nearer by more than
  /// the sensor's edge_jump_m); the disparity fx b / d then gets the fields' and the pixel's errors
  /// and is rounded to disparity_step_px.
  double Depth(int u, int v, double depth_m, uint64_t key) const;

 private:
  const StructuredLightParams& params_;
  double focal_baseline_px_m_;  ///< [px m] fx * baseline
  double edge_jump_m_;
  SmoothField fixed_, frame_;
  cv::Mat nearest_m_;  ///< CV_32FC1 minimum true depth within bleed_px (empty without bleeding)
};

}  // namespace synth
}  // namespace dslam
