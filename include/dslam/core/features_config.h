#pragma once
// Config sections of the `features` area: depth noise model, ORB extraction and motion-only pose
// estimation. Members of the one Config tree (config.h); kept in their own header so that the
// feature, depth-uncertainty and pose modules can include them without the whole tree.

#include "dslam/core/config_field.h"

namespace dslam {

/// RGB-D point measurement noise (paper Sec. V-A; Khoshelham depth noise, Dryanovski mixture).
struct DepthNoiseConfig {
  double pixel_sigma_px = 1.0;         ///< [px] sigma_u = sigma_v at level 0 (x scale^level)
  double sigma_d_quadratic = 1.4e-3;   ///< [1/m] a in sigma_d = a d^2 + b
  double sigma_d_constant_m = 1.0e-3;  ///< [m] b in sigma_d = a d^2 + b
  double min_depth_m = 0.3;            ///< [m] smaller depths count as no measurement
  double max_depth_m = 6.0;            ///< [m] larger depths count as no measurement
  int min_valid_window_pixels = 5;     ///< [-] of the 3x3 window (centre included) needed valid

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    v(FieldInfo{"pixel_sigma_px", "px", 0.01, 10.0, "keypoint sigma_u = sigma_v at pyramid level 0 (x scale^level)", {}},
      s.pixel_sigma_px);
    v(FieldInfo{"sigma_d_quadratic", "1/m", 0.0, 0.1, "a in depth sigma_d = a d^2 + b", {}},
      s.sigma_d_quadratic);
    v(FieldInfo{"sigma_d_constant_m", "m", 0.0, 0.1, "b in depth sigma_d = a d^2 + b", {}},
      s.sigma_d_constant_m);
    v(FieldInfo{"min_depth_m", "m", 0.0, 100.0, "smallest valid depth", {}}, s.min_depth_m);
    v(FieldInfo{"max_depth_m", "m", 0.0, 100.0, "largest valid depth", {}}, s.max_depth_m);
    v(FieldInfo{"min_valid_window_pixels", "-", 1, 9, "valid depths needed of the 3x3 window", {}},
      s.min_valid_window_pixels);
  }
};

/// ORB extraction spread over the image (features.h).
struct FeaturesConfig {
  int num_features = 1000;     ///< [-] requested keypoints over all pyramid levels
  int num_levels = 8;          ///< [-] pyramid levels (octaves)
  double scale_factor = 1.2;   ///< [-] scale between consecutive pyramid levels
  int fast_threshold = 20;     ///< [-] FAST intensity threshold (grey levels)
  int fast_threshold_min = 7;  ///< [-] fallback FAST threshold in cells where nothing was found
  int cell_size_px = 30;       ///< [px] side of a detection grid cell (at each level)

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    v(FieldInfo{"num_features", "-", 10, 20000, "ORB keypoints requested per frame", {}},
      s.num_features);
    v(FieldInfo{"num_levels", "-", 1, 16, "ORB pyramid levels", {}}, s.num_levels);
    v(FieldInfo{"scale_factor", "-", 1.01, 2.0, "scale between pyramid levels", {}},
      s.scale_factor);
    v(FieldInfo{"fast_threshold", "-", 1, 255, "FAST threshold (grey levels)", {}},
      s.fast_threshold);
    v(FieldInfo{"fast_threshold_min", "-", 1, 255, "fallback FAST threshold for weak cells", {}},
      s.fast_threshold_min);
    v(FieldInfo{"cell_size_px", "px", 10, 200, "detection grid cell side at every level", {}},
      s.cell_size_px);
  }
};

/// Motion-only bundle adjustment (pose_optimizer.h) and its RANSAC initialisation.
struct PoseConfig {
  double huber_delta_depth = 2.796;  ///< [-] Huber width on the whitened 3-dof residual
  double huber_delta_pixel = 2.448;  ///< [-] Huber width on the whitened 2-dof residual
  double chi2_depth = 7.815;         ///< [-] inlier bound on squared Mahalanobis error, 3 dof (95%)
  double chi2_pixel = 5.991;         ///< [-] inlier bound on squared Mahalanobis error, 2 dof (95%)
  int rounds = 4;                    ///< [-] optimise / classify rounds
  int max_iterations = 10;           ///< [-] Levenberg-Marquardt iterations per round
  int ransac_max_iterations = 300;   ///< [-] RANSAC hypotheses at most
  double ransac_confidence = 0.999;  ///< [-] adaptive stopping confidence
  double ransac_extra_sigma_m = 0.01;  ///< [m] isotropic sigma added to C for the inlier test

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    v(FieldInfo{"huber_delta_depth", "-", 0.1, 100.0, "Huber width, whitened 3-dof residual", {}},
      s.huber_delta_depth);
    v(FieldInfo{"huber_delta_pixel", "-", 0.1, 100.0, "Huber width, whitened 2-dof residual", {}},
      s.huber_delta_pixel);
    v(FieldInfo{"chi2_depth", "-", 0.1, 1000.0, "inlier chi-square bound, 3 dof", {}},
      s.chi2_depth);
    v(FieldInfo{"chi2_pixel", "-", 0.1, 1000.0, "inlier chi-square bound, 2 dof", {}},
      s.chi2_pixel);
    v(FieldInfo{"rounds", "-", 1, 20, "optimise/classify rounds", {}}, s.rounds);
    v(FieldInfo{"max_iterations", "-", 1, 1000, "solver iterations per round", {}},
      s.max_iterations);
    v(FieldInfo{"ransac_max_iterations", "-", 1, 100000, "RANSAC hypotheses at most", {}},
      s.ransac_max_iterations);
    v(FieldInfo{"ransac_confidence", "-", 0.5, 0.999999, "RANSAC stopping confidence", {}},
      s.ransac_confidence);
    v(FieldInfo{"ransac_extra_sigma_m", "m", 0.0, 1.0, "sigma added to C in RANSAC tests", {}},
      s.ransac_extra_sigma_m);
  }
};

}  // namespace dslam
