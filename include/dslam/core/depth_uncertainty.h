#pragma once
// RGB-D map-point measurement y_ik and its 3x3 covariance C_ik (paper Sec. V-A, Eq. rgbd_yik,
// Eq. mix_gauss and the C_ik equations). The paper prints (u-c_u)(v-c_v) in sigma_a^2 and
// sigma_b^2; the variance of a = (u-c_u) c / f_u is [(u-c_u)^2 sigma_c^2 + sigma_u^2 (mu_c^2 +
// sigma_c^2)] / f_u^2 (and (v-c_v)^2 for b), as in the paper's source, Dryanovski et al. (ICRA
// 2013); PointCovariance computes that.

#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/core/camera.h"
#include "dslam/core/features_config.h"

namespace dslam {

/// One back-projected keypoint with its uncertainty, in the camera's optical frame.
struct PointMeasurement {
  Eigen::Vector3d y_camera;    ///< [m] y = [(u-c_u) mu_c/f_u, (v-c_v) mu_c/f_v, mu_c]
  Eigen::Matrix3d covariance;  ///< [m^2] C of y (symmetric positive definite)
  double depth_mean_m = 0.0;   ///< [m] mu_c, mean of the 3x3 Gaussian mixture
  double depth_sigma_m = 0.0;  ///< [m] sigma_c, standard deviation of the mixture
};

/// The measurement expressed in another frame: y' = T y, C' = R C R^T (R = T's rotation), e.g.
/// T_world_camera for a camera-frame measurement in the world frame.
PointMeasurement Transformed(const PointMeasurement& m, const Eigen::Isometry3d& T);

/// Khoshelham-style depth noise sigma_d = a d^2 + b [m] for a depth d [m].
double DepthSigma(double depth_m, const DepthNoiseConfig& config);

/// Mixture mean mu_c [m] and variance sigma_c^2 [m^2] of the depths around a pixel.
struct DepthMixture {
  double mean_m = 0.0;
  double variance_m2 = 0.0;
};

/// Gaussian mixture of Eq. mix_gauss over the 3x3 window centred on integer pixel (col, row) of
/// `depth_m` (CV_32FC1, metres, 0 = none) with kernel W = 1/16 [1 2 1; 2 4 2; 1 2 1]. Each
/// component is N(d_q, sigma_d(d_q)^2). Invalid neighbours (0, NaN, outside the image or outside
/// [min_depth_m, max_depth_m]) are dropped and the remaining weights renormalised to sum 1.
/// Returns nothing when the centre is invalid or fewer than 5 of the nine
/// window pixels (centre included) are valid.
std::optional<DepthMixture> MixDepth(const cv::Mat& depth_m, int col, int row,
                                     const DepthNoiseConfig& config);

/// Covariance C [m^2] of y = [(u-c_u) c/f_u, (v-c_v) c/f_v, c] for independent u ~ N(u, s_u^2),
/// v ~ N(v, s_v^2) [px] and c ~ (mu_c, sigma_c^2) [m] at ideal pixel `uv_ideal` [px]:
///   sigma_a^2 = [(u-c_u)^2 sigma_c^2 + s_u^2 (mu_c^2 + sigma_c^2)] / f_u^2   (typo fixed)
///   sigma_b^2 = [(v-c_v)^2 sigma_c^2 + s_v^2 (mu_c^2 + sigma_c^2)] / f_v^2   (typo fixed)
///   sigma_ab = sigma_c^2 (u-c_u)(v-c_v)/(f_u f_v), sigma_ac = sigma_c^2 (u-c_u)/f_u,
///   sigma_bc = sigma_c^2 (v-c_v)/f_v, sigma_c^2.
Eigen::Matrix3d PointCovariance(const Eigen::Vector2d& uv_ideal, const DepthMixture& mixture,
                                double pixel_sigma_px, const PinholeCamera& camera);

/// The paper's RGB-D map-point measurement. Depth is read around `uv_pixel` (raw pixel where the
/// keypoint was detected, rounded to the nearest integer pixel, [px]) of the registered depth
/// image; the point is back-projected from `uv_ideal` (undistorted pixel, [px]) with the mixture
/// mean mu_c as depth. Returns nothing when MixDepth() rejects the window. Pixel noise is applied
/// to the ideal pixel (the distortion Jacobian is ignored: it is ~1 for Kinect-class lenses).
std::optional<PointMeasurement> MeasurePoint(const cv::Mat& depth_m,
                                             const Eigen::Vector2d& uv_pixel,
                                             const Eigen::Vector2d& uv_ideal,
                                             const PinholeCamera& camera,
                                             const DepthNoiseConfig& config);

}  // namespace dslam
