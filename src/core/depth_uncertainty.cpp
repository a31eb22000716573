#include "dslam/core/depth_uncertainty.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dslam/core/geometry.h"

namespace dslam {
namespace {

// Valid depths MixDepth needs of the 3x3 window (its centre included).
constexpr int kMinValidWindowPixels = 5;

bool ValidDepth(float d, const DepthNoiseConfig& config) {
  return std::isfinite(d) && d > 0.0f && d >= config.min_depth_m && d <= config.max_depth_m;
}

}  // namespace

double DepthSigma(double depth_m, const DepthNoiseConfig& config) {
  return config.sigma_d_quadratic * depth_m * depth_m + config.sigma_d_constant_m;
}

std::optional<DepthMixture> MixDepth(const cv::Mat& depth_m, int col, int row,
                                     const DepthNoiseConfig& config) {
  if (depth_m.type() != CV_32FC1) throw std::invalid_argument("MixDepth: depth must be CV_32FC1");
  if (col < 0 || row < 0 || col >= depth_m.cols || row >= depth_m.rows) return std::nullopt;
  if (!ValidDepth(depth_m.at<float>(row, col), config)) return std::nullopt;
  static constexpr double kKernel[3][3] = {{1, 2, 1}, {2, 4, 2}, {1, 2, 1}};  // x 1/16
  double weight_sum = 0.0, first = 0.0, second = 0.0;
  int valid = 0;
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      const int r = row + dr, c = col + dc;
      if (r < 0 || c < 0 || r >= depth_m.rows || c >= depth_m.cols) continue;
      const float d = depth_m.at<float>(r, c);
      if (!ValidDepth(d, config)) continue;
      const double w = kKernel[dr + 1][dc + 1];
      const double sigma = DepthSigma(d, config);
      weight_sum += w;
      first += w * d;
      second += w * (sigma * sigma + static_cast<double>(d) * d);
      ++valid;
    }
  }
  if (valid < kMinValidWindowPixels) return std::nullopt;
  DepthMixture mixture;
  mixture.mean_m = first / weight_sum;
  // Eq. mix_gauss: sigma_c^2 = sum w (sigma_d^2 + d^2) - mu_c^2 (clamped against round-off).
  mixture.variance_m2 = std::max(second / weight_sum - mixture.mean_m * mixture.mean_m, 1e-12);
  return mixture;
}

Eigen::Matrix3d PointCovariance(const Eigen::Vector2d& uv_ideal, const DepthMixture& mixture,
                                double pixel_sigma_px, const PinholeCamera& camera) {
  const double du = uv_ideal.x() - camera.cx(), dv = uv_ideal.y() - camera.cy();
  const double fu = camera.fx(), fv = camera.fy();
  const double var_c = mixture.variance_m2;
  const double second_moment = mixture.mean_m * mixture.mean_m + var_c;
  const double var_px = pixel_sigma_px * pixel_sigma_px;
  Eigen::Matrix3d c;
  c(0, 0) = (du * du * var_c + var_px * second_moment) / (fu * fu);
  c(1, 1) = (dv * dv * var_c + var_px * second_moment) / (fv * fv);
  c(2, 2) = var_c;
  c(0, 1) = c(1, 0) = var_c * du * dv / (fu * fv);
  c(0, 2) = c(2, 0) = var_c * du / fu;
  c(1, 2) = c(2, 1) = var_c * dv / fv;
  return c;
}

std::optional<PointMeasurement> MeasurePoint(const cv::Mat& depth_m,
                                             const Eigen::Vector2d& uv_pixel,
                                             const Eigen::Vector2d& uv_ideal,
                                             const PinholeCamera& camera,
                                             const DepthNoiseConfig& config) {
  const int col = static_cast<int>(std::lround(uv_pixel.x()));
  const int row = static_cast<int>(std::lround(uv_pixel.y()));
  const std::optional<DepthMixture> mixture = MixDepth(depth_m, col, row, config);
  if (!mixture) return std::nullopt;
  PointMeasurement m;
  m.depth_mean_m = mixture->mean_m;
  m.depth_sigma_m = std::sqrt(mixture->variance_m2);
  m.y_camera = camera.BackProject(uv_ideal, mixture->mean_m);
  m.covariance = PointCovariance(uv_ideal, *mixture, config.pixel_sigma_px, camera);
  return m;
}

PointMeasurement Transformed(const PointMeasurement& m, const Eigen::Isometry3d& T) {
  PointMeasurement out = m;
  out.y_camera = T * m.y_camera;
  out.covariance = RotatedCovariance(T.rotation(), m.covariance);
  return out;
}

}  // namespace dslam
