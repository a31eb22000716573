#pragma once
// Config sections of the `features` area: depth noise model, ORB extraction and motion-only pose
// estimation. Members of the one Config tree (config.h); kept in their own header so that the
// feature, depth-uncertainty and pose modules can include them without the whole tree.

#include "dslam/core/config_field.h"

namespace dslam {

/// RGB-D point measurement noise (paper Sec. V-A; Khoshelham depth noise, Dryanovski mixture).
/// Units, ranges and meanings of the fields are given in Fields() (printed by
/// `dslam_config_doc`).
struct DepthNoiseConfig {
  double pixel_sigma_px = 1.0;
  double sigma_d_quadratic = 8.0e-3;
  double sigma_d_constant_m = 1.0e-3;
  double min_depth_m = 0.3;
  double max_depth_m = 6.0;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    v(Field("pixel_sigma_px", "px", 0.01, 10.0,
            "keypoint sigma_u = sigma_v at pyramid level 0 (x scale^level)"),
      s.pixel_sigma_px);
    // 0.008: what the pose needs from a structured-light camera (Kinect v1, Xtion; fitted on
    // TUM and Bonn frames, docs/benchmarks/tracking.md "Issue 46"), whose depth errors are
    // correlated over the image and over frames; a camera.yaml may state its camera's own
    // (dataset_io.h).
    v(Field("sigma_d_quadratic", "1/m", 0.0, 0.1, "a in depth sigma_d = a d^2 + b"),
      s.sigma_d_quadratic);
    v(Field("sigma_d_constant_m", "m", 0.0, 0.1, "b in depth sigma_d = a d^2 + b"),
      s.sigma_d_constant_m);
    // Depths outside [min_depth_m, max_depth_m] count as no measurement.
    v(Field("min_depth_m", "m", 0.0, 100.0, "smallest valid depth"), s.min_depth_m);
    v(Field("max_depth_m", "m", 0.0, 100.0, "largest valid depth"), s.max_depth_m);
  }
};

/// ORB extraction spread over the image (features.h). Units, ranges and meanings of the fields
/// are given in Fields() (printed by `dslam_config_doc`).
struct FeaturesConfig {
  int num_features = 1000;
  int num_levels = 8;
  double scale_factor = 1.2;
  int fast_threshold = 20;
  int fast_threshold_min = 7;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    // num_features counts keypoints over all pyramid levels.
    v(Field("num_features", "-", 10, 20000, "ORB keypoints requested per frame"), s.num_features);
    v(Field("num_levels", "-", 1, 16, "ORB pyramid levels"), s.num_levels);
    v(Field("scale_factor", "-", 1.01, 2.0, "scale between pyramid levels"), s.scale_factor);
    v(Field("fast_threshold", "-", 1, 255, "FAST threshold (grey levels)"), s.fast_threshold);
    // Used in grid cells where fast_threshold found nothing.
    v(Field("fast_threshold_min", "-", 1, 255, "fallback FAST threshold for weak cells"),
      s.fast_threshold_min);
  }
};

/// Motion-only bundle adjustment (pose_optimizer.h, solved by the hand-written Levenberg-Marquardt
/// of pose_solver_lm.cpp) and its RANSAC initialisation (robust_pose.h). Units, ranges
/// and meanings of the fields are given in Fields() (printed by `dslam_config_doc`).
struct PoseConfig {
  double huber_delta_depth = 2.796;
  double huber_delta_pixel = 2.448;
  double chi2_depth = 7.815;
  double chi2_pixel = 5.991;
  int rounds = 4;
  int max_iterations = 10;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    v(Field("huber_delta_depth", "-", 0.1, 100.0, "Huber width, whitened 3-dof residual"),
      s.huber_delta_depth);
    v(Field("huber_delta_pixel", "-", 0.1, 100.0, "Huber width, whitened 2-dof residual"),
      s.huber_delta_pixel);
    // Bounds on the squared Mahalanobis error; the defaults are the 95% quantiles.
    v(Field("chi2_depth", "-", 0.1, 1000.0, "inlier chi-square bound, 3 dof"), s.chi2_depth);
    v(Field("chi2_pixel", "-", 0.1, 1000.0, "inlier chi-square bound, 2 dof"), s.chi2_pixel);
    v(Field("rounds", "-", 1, 20, "optimise/classify rounds"), s.rounds);
    // Levenberg-Marquardt iterations.
    v(Field("max_iterations", "-", 1, 1000, "solver iterations per round"), s.max_iterations);
  }
};

}  // namespace dslam
