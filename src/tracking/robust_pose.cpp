#include "dslam/tracking/robust_pose.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Geometry>

namespace dslam {
namespace {

constexpr double kMinTriangleArea = 1e-4;  // [m^2]
constexpr double kRigidSigmas = 5.0;

// Rigid transform T (world -> camera) fitted to the selected observations (Umeyama, no scale).
Eigen::Isometry3d Fit(const std::vector<PoseObservation>& obs, const std::vector<int>& idx) {
  Eigen::Matrix3Xd src(3, idx.size()), dst(3, idx.size());
  for (size_t k = 0; k < idx.size(); ++k) {
    src.col(k) = obs[idx[k]].p_world;
    dst.col(k) = obs[idx[k]].y_camera;
  }
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.matrix() = Eigen::umeyama(src, dst, false);
  return T;
}

bool SampleIsValid(const std::vector<PoseObservation>& obs, const int s[3]) {
  const Eigen::Vector3d& a = obs[s[0]].p_world;
  if (0.5 * (obs[s[1]].p_world - a).cross(obs[s[2]].p_world - a).norm() < kMinTriangleArea) {
    return false;
  }
  for (int i = 0; i < 3; ++i) {
    const PoseObservation& u = obs[s[i]];
    const PoseObservation& v = obs[s[(i + 1) % 3]];
    const double world = (u.p_world - v.p_world).norm();
    const double camera = (u.y_camera - v.y_camera).norm();
    const double sigma = std::sqrt(u.covariance.trace() + v.covariance.trace());
    if (std::abs(world - camera) > kRigidSigmas * sigma + 0.05 * world) return false;
  }
  return true;
}

struct Score {
  int inliers = 0;
  double error = 0.0;
};

Score Evaluate(const std::vector<PoseObservation>& obs, const std::vector<Eigen::Matrix3d>& info,
               const Eigen::Isometry3d& T, double chi2, std::vector<bool>* inliers) {
  Score score;
  inliers->assign(obs.size(), false);
  for (size_t i = 0; i < obs.size(); ++i) {
    if (!obs[i].has_depth) continue;
    const Eigen::Vector3d e = T * obs[i].p_world - obs[i].y_camera;
    const double d2 = e.dot(info[i] * e);
    if (d2 >= chi2) continue;
    (*inliers)[i] = true;
    ++score.inliers;
    score.error += d2;
  }
  return score;
}

int RequiredHypotheses(double inlier_ratio, double confidence, int max_iterations) {
  const double w3 = std::pow(inlier_ratio, 3);
  if (w3 >= 1.0 - 1e-12) return 1;
  if (w3 <= 1e-12) return max_iterations;
  const double n = std::log(1.0 - confidence) / std::log(1.0 - w3);
  return static_cast<int>(std::min<double>(max_iterations, std::ceil(n)));
}

}  // namespace

RansacResult RansacPose(const std::vector<PoseObservation>& obs, const PoseConfig& config,
                        std::uint32_t seed) {
  RansacResult result;
  result.inliers.assign(obs.size(), false);
  std::vector<int> depth_idx;
  std::vector<Eigen::Matrix3d> info(obs.size(), Eigen::Matrix3d::Zero());
  const double s2 = kRansacExtraSigmaM * kRansacExtraSigmaM;
  for (size_t i = 0; i < obs.size(); ++i) {
    if (!obs[i].has_depth) continue;
    depth_idx.push_back(static_cast<int>(i));
    info[i] = (obs[i].covariance + s2 * Eigen::Matrix3d::Identity()).inverse();
  }
  if (depth_idx.size() < 3) return result;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<size_t> pick(0, depth_idx.size() - 1);
  Score best;
  int needed = kRansacMaxHypotheses;
  std::vector<bool> inliers;
  for (int it = 0; it < needed; ++it) {
    int s[3] = {depth_idx[pick(rng)], depth_idx[pick(rng)], depth_idx[pick(rng)]};
    ++result.hypotheses;
    if (s[0] == s[1] || s[1] == s[2] || s[0] == s[2] || !SampleIsValid(obs, s)) continue;
    const Eigen::Isometry3d T = Fit(obs, {s[0], s[1], s[2]});
    const Score score = Evaluate(obs, info, T, config.chi2_depth, &inliers);
    if (score.inliers > best.inliers ||
        (score.inliers == best.inliers && score.error < best.error)) {
      best = score;
      result.T_camera_world = T;
      result.inliers = inliers;
      needed = RequiredHypotheses(static_cast<double>(best.inliers) / depth_idx.size(),
                                  kRansacConfidence, kRansacMaxHypotheses);
    }
  }
  if (best.inliers < 3) return result;
  std::vector<int> idx;
  for (size_t i = 0; i < obs.size(); ++i) {
    if (result.inliers[i]) idx.push_back(static_cast<int>(i));
  }
  result.T_camera_world = Fit(obs, idx);
  result.num_inliers =
      Evaluate(obs, info, result.T_camera_world, config.chi2_depth, &result.inliers).inliers;
  result.success = result.num_inliers >= 3;
  return result;
}

PoseResult EstimatePoseRobust(const std::vector<PoseObservation>& observations,
                              const PinholeCamera& camera, const PoseConfig& config,
                              std::uint32_t seed, PoseSolver solver) {
  const RansacResult ransac = RansacPose(observations, config, seed);
  if (!ransac.success) {
    PoseResult failed;
    failed.inliers.assign(observations.size(), false);
    return failed;
  }
  // First BA round: RANSAC inliers plus the pixel-only observations consistent with its pose.
  std::vector<bool> initial = ransac.inliers;
  for (size_t i = 0; i < observations.size(); ++i) {
    if (observations[i].has_depth) continue;
    initial[i] = SquaredError(observations[i], ransac.T_camera_world, camera) < config.chi2_pixel;
  }
  return EstimatePose(observations, ransac.T_camera_world, camera, config, &initial, solver);
}

}  // namespace dslam
