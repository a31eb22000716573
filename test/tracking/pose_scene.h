#pragma once
// Pose-estimation test scene: map points seen by a camera at a known pose, RGB-D
// measurements with noise drawn from the model covariance, and gross outliers.

#include <random>
#include <vector>

#include <Eigen/Cholesky>

#include "dslam/tracking/pose_optimizer.h"

namespace dslam {
namespace test {

struct PoseScene {
  Eigen::Isometry3d T_camera_world;
  std::vector<PoseObservation> observations;
  std::vector<bool> is_outlier;
};

/// Known camera pose; `n` points at 1-4 m depth; a fraction `outliers` of the measurements moved by
/// 0.3-1.0 m; every `pixel_only_every`-th observation (0: none) without depth.
inline PoseScene MakePoseScene(const PinholeCamera& camera, int n, double outliers, unsigned seed,
                               int pixel_only_every = 0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  PoseScene scene;
  scene.T_camera_world = Eigen::Translation3d(0.3, -0.2, 1.1) *
                         Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.2, 1.0, -0.3).normalized());
  const DepthNoiseConfig noise;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d uv(20.0 + 600.0 * uni(rng), 20.0 + 440.0 * uni(rng));
    const double depth = 1.0 + 3.0 * uni(rng);
    const Eigen::Vector3d p_camera = camera.BackProject(uv, depth);
    const Eigen::Vector3d p_world = scene.T_camera_world.inverse() * p_camera;
    const double sigma_d = DepthSigma(depth, noise);
    const Eigen::Matrix3d C = PointCovariance(uv, {depth, sigma_d * sigma_d}, 1.0, camera);
    const Eigen::Vector3d noise_sample =
        C.llt().matrixL() * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
    const bool outlier = uni(rng) < outliers;
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    if (outlier) {
      offset = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized() *
               (0.3 + 0.7 * uni(rng));
    }
    if (pixel_only_every > 0 && i % pixel_only_every == 0) {
      const Eigen::Vector2d uv_noisy =
          uv + Eigen::Vector2d(normal(rng), normal(rng)) +
          (outlier ? Eigen::Vector2d(40.0, -30.0) : Eigen::Vector2d(0, 0));
      scene.observations.push_back(PoseObservation::PixelOnly(p_world, uv_noisy, 1.0));
    } else {
      PointMeasurement m;
      m.y_camera = p_camera + noise_sample + offset;
      m.covariance = C;
      scene.observations.push_back(PoseObservation::WithDepth(p_world, m));
    }
    scene.is_outlier.push_back(outlier);
  }
  return scene;
}

inline double RotationErrorDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.rotation().transpose() * b.rotation()).angle() * 180.0 / M_PI;
}

}  // namespace test
}  // namespace dslam
