// Sensor model of the synthetic RGB-D camera (sequence.h: ApplySensorModel).
#include <algorithm>
#include <cmath>
#include <optional>

#include "dslam/synth/sequence.h"
#include "dslam/synth/structured_light.h"
#include "sensor_noise.h"

namespace dslam {
namespace synth {
namespace {

/// Approximately normal sample with unit variance: sum of four 16-bit uniforms (Irwin-Hall),
/// cheap enough for the three colour channels of every pixel.
float FastGaussian(uint64_t key) {
  const uint64_t h = Mix64(key);
  const float sum =
      static_cast<float>((h & 0xffff) + ((h >> 16) & 0xffff) + ((h >> 32) & 0xffff) + (h >> 48)) *
      (1.0f / 65536.0f);
  return (sum - 2.0f) * 1.7320508f;  // variance of the sum is 4/12
}

bool IsEdge(const cv::Mat& depth, int v, int u, double jump_m) {
  const float d = depth.at<float>(v, u);
  const int du[4] = {1, -1, 0, 0}, dv[4] = {0, 0, 1, -1};
  for (int k = 0; k < 4; ++k) {
    const int uu = u + du[k], vv = v + dv[k];
    if (uu < 0 || vv < 0 || uu >= depth.cols || vv >= depth.rows) continue;
    if (std::abs(depth.at<float>(vv, uu) - d) > jump_m) return true;
  }
  return false;
}

}  // namespace

void ApplySensorModel(const SensorParams& s, uint32_t seed, int index, const cv::Mat& colour_clean,
                      const cv::Mat& depth_true_m, cv::Mat* colour, cv::Mat* depth_units) {
  const uint64_t frame_key =
      Mix64((static_cast<uint64_t>(seed) << 32) ^ static_cast<uint32_t>(index));
  *colour = cv::Mat(colour_clean.size(), CV_8UC3);
  *depth_units = cv::Mat(depth_true_m.size(), CV_16UC1, cv::Scalar(0));
  const uint64_t n = static_cast<uint64_t>(colour_clean.total());
  std::optional<StructuredLightFrame> structured_light;
  if (s.structured_light.enabled) structured_light.emplace(s, seed, frame_key, depth_true_m);
  cv::parallel_for_(
      cv::Range(0, colour_clean.rows),
      [&](const cv::Range& rows) {
        for (int v = rows.start; v < rows.end; ++v) {
          for (int u = 0; u < colour_clean.cols; ++u) {
            const uint64_t pixel = static_cast<uint64_t>(v) * colour_clean.cols + u;
            const cv::Vec3b& in = colour_clean.at<cv::Vec3b>(v, u);
            cv::Vec3b& out = colour->at<cv::Vec3b>(v, u);
            for (int c = 0; c < 3; ++c) {
              const float noisy = in[c] + static_cast<float>(s.colour_sigma) *
                                              FastGaussian(frame_key ^ Mix64(pixel + c * n));
              out[c] = static_cast<uint8_t>(std::min(255.0f, std::max(0.0f, std::round(noisy))));
            }
            const double d = depth_true_m.at<float>(v, u);
            if (d < s.min_depth_m || d > s.max_depth_m) continue;
            const uint64_t key = frame_key ^ Mix64(pixel + 3 * n);
            if (IsEdge(depth_true_m, v, u, s.edge_jump_m) &&
                Unit(Mix64(key ^ 0x5bd1e995ull)) < s.edge_dropout_probability) {
              continue;
            }
            double measured_m = 0.0;
            if (structured_light) {
              measured_m = structured_light->Depth(u, v, d, key);
              if (!(measured_m > 0.0)) continue;
            } else {
              const double sigma = s.depth_sigma_quadratic_per_m * d * d + s.depth_sigma_constant_m;
              measured_m = d + sigma * Gaussian(key);
            }
            const double units = std::round(measured_m * s.depth_scale);
            depth_units->at<uint16_t>(v, u) =
                static_cast<uint16_t>(std::max(1.0, std::min(65535.0, units)));
          }
        }
      },
      8);
}

}  // namespace synth
}  // namespace dslam
