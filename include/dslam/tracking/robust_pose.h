#pragma once
// RANSAC over 3D-3D correspondences (map point in world <-> RGB-D measurement in camera) for
// tracking recovery and when the static set is too small, refined by the motion-only BA.
//
// Hypotheses: 3 distinct observations with depth drawn with a seeded std::mt19937; rejected when
// the triangle is degenerate (area < 1e-4 m^2) or the pairwise distances differ between world and
// camera by more than 5 sigma (rigid-motion check); pose by Umeyama/Horn (no scale). Inlier:
// e^T (C + s^2 I)^-1 e < chi2_depth, e = T_cw p_w - y, s = kRansacExtraSigmaM (the map point's
// own error), so the metric threshold grows with depth through C. The best hypothesis (most
// inliers, then least summed error) is refitted on its inliers; adaptive stopping after
// log(1 - kRansacConfidence) / log(1 - w^3) hypotheses (w = best inlier ratio), at most
// kRansacMaxHypotheses.

#include <cstdint>
#include <vector>

#include "dslam/tracking/pose_optimizer.h"

namespace dslam {

constexpr int kRansacMaxHypotheses = 300;    ///< RANSAC hypotheses at most
constexpr double kRansacConfidence = 0.999;  ///< [-] RANSAC stopping confidence
constexpr double kRansacExtraSigmaM = 0.01;  ///< [m] sigma added to C in the inlier test

/// RANSAC result (before refinement).
struct RansacResult {
  bool success = false;  ///< false: fewer than 3 depth observations or no valid hypothesis
  Eigen::Isometry3d T_camera_world = Eigen::Isometry3d::Identity();
  std::vector<bool> inliers;  ///< per observation; pixel-only observations are always false
  int num_inliers = 0;
  int hypotheses = 0;  ///< hypotheses evaluated
};

/// RANSAC as described at the top of this file; only observations with has_depth take part.
RansacResult RansacPose(const std::vector<PoseObservation>& observations, const PoseConfig& config,
                        std::uint32_t seed = 1);

/// RansacPose() then EstimatePose() over all observations (pixel-only included) started from the
/// RANSAC pose, solved by `solver`; returns the BA result (success false when RANSAC failed).
PoseResult EstimatePoseRobust(const std::vector<PoseObservation>& observations,
                              const PinholeCamera& camera, const PoseConfig& config,
                              std::uint32_t seed = 1,
                              PoseSolver solver = PoseSolver::kLevenbergMarquardt);

}  // namespace dslam
