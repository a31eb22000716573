#include "dslam/core/depth_uncertainty.h"

#include <random>

#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

namespace dslam {
namespace {

PinholeCamera TestCamera() { return PinholeCamera(640, 480, 525.0, 520.0, 319.5, 239.5); }

TEST(DepthUncertainty, FlatDepthGivesModelVariance) {
  DepthNoiseConfig config;
  config.sigma_d_quadratic = 1.4e-3;
  config.sigma_d_constant_m = 1e-3;
  const cv::Mat depth(480, 640, CV_32FC1, cv::Scalar(2.0));
  const auto mixture = MixDepth(depth, 100, 200, config);
  ASSERT_TRUE(mixture.has_value());
  const double sigma_d = 1.4e-3 * 4.0 + 1e-3;
  EXPECT_NEAR(mixture->mean_m, 2.0, 1e-9);
  EXPECT_NEAR(mixture->variance_m2, sigma_d * sigma_d, 1e-9);
  EXPECT_NEAR(DepthSigma(2.0, config), sigma_d, 1e-12);
}

TEST(DepthUncertainty, DepthEdgeInflatesSigma) {
  const DepthNoiseConfig config;
  cv::Mat depth(480, 640, CV_32FC1, cv::Scalar(1.0));
  depth.colRange(101, 640).setTo(3.0);  // edge between columns 100 and 101
  const auto edge = MixDepth(depth, 100, 200, config);
  const auto flat = MixDepth(depth, 50, 200, config);
  ASSERT_TRUE(edge && flat);
  // Weights 3/4 on 1 m, 1/4 on 3 m: mean 1.5 m, spread variance 0.75 m^2 plus the noise.
  EXPECT_NEAR(edge->mean_m, 1.5, 1e-6);
  EXPECT_GT(edge->variance_m2, 0.75);
  EXPECT_GT(edge->variance_m2, 1000.0 * flat->variance_m2);
}

TEST(DepthUncertainty, RejectsInvalidCentreAndSparseWindow) {
  DepthNoiseConfig config;
  cv::Mat depth(480, 640, CV_32FC1, cv::Scalar(2.0));
  depth.at<float>(200, 100) = 0.0f;
  EXPECT_FALSE(MixDepth(depth, 100, 200, config));
  depth.at<float>(200, 100) = 10.0f;  // beyond max_depth_m
  EXPECT_FALSE(MixDepth(depth, 100, 200, config));
  depth.at<float>(200, 100) = 2.0f;
  depth.rowRange(199, 200).setTo(0.0);  // rows 199 and 201 empty: 3 of 9 valid
  depth.rowRange(201, 202).setTo(0.0);
  EXPECT_FALSE(MixDepth(depth, 100, 200, config));
  depth.rowRange(201, 202).setTo(2.0);  // row 199 empty: 6 of 9 valid, at least 5
  const auto renormalised = MixDepth(depth, 100, 200, config);
  ASSERT_TRUE(renormalised);
  EXPECT_NEAR(renormalised->mean_m, 2.0, 1e-9);  // weights renormalised over valid pixels
  EXPECT_FALSE(MixDepth(depth, -1, 200, config));
}

TEST(DepthUncertainty, MeasurePointBackProjectsAndIsSpd) {
  const PinholeCamera camera = TestCamera();
  const cv::Mat depth(480, 640, CV_32FC1, cv::Scalar(2.5));
  const Eigen::Vector2d uv(600.2, 50.7);
  const auto m = MeasurePoint(depth, uv, uv, camera, DepthNoiseConfig());
  ASSERT_TRUE(m);
  EXPECT_NEAR((camera.Project(m->y_camera) - uv).norm(), 0.0, 1e-9);
  EXPECT_NEAR(m->y_camera.z(), 2.5, 1e-9);
  EXPECT_NEAR((m->covariance - m->covariance.transpose()).norm(), 0.0, 1e-18);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m->covariance);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
}

// Samples u, v and the mixture depth c from the model, back-projects and compares the empirical
// covariance of y with C (checks the corrected sigma_a^2 / sigma_b^2 including (u-c_u)^2).
TEST(DepthUncertainty, MonteCarloMatchesCovariance) {
  const PinholeCamera camera = TestCamera();
  DepthNoiseConfig config;
  config.pixel_sigma_px = 2.0;
  cv::Mat depth(480, 640, CV_32FC1, cv::Scalar(2.0));
  depth.colRange(51, 640).setTo(2.6);     // an edge in the window makes sigma_c large
  const Eigen::Vector2d uv(50.0, 430.0);  // far from the principal point: large off-diagonals
  const auto m = MeasurePoint(depth, uv, uv, camera, config);
  ASSERT_TRUE(m);
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::discrete_distribution<int> pick({1, 2, 1, 2, 4, 2, 1, 2, 1});
  const int n = 200000;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (int i = 0; i < n; ++i) {
    const int q = pick(rng);
    const double d_q = depth.at<float>(430 + q / 3 - 1, 50 + q % 3 - 1);
    const double c = d_q + DepthSigma(d_q, config) * normal(rng);
    const Eigen::Vector2d uv_s =
        uv + config.pixel_sigma_px * Eigen::Vector2d(normal(rng), normal(rng));
    const Eigen::Vector3d y = camera.BackProject(uv_s, c);
    mean += y;
    second += y * y.transpose();
  }
  mean /= n;
  const Eigen::Matrix3d empirical = second / n - mean * mean.transpose();
  EXPECT_NEAR((mean - m->y_camera).norm(), 0.0, 2e-3);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      const double scale = std::sqrt(m->covariance(r, r) * m->covariance(c, c));
      EXPECT_NEAR(empirical(r, c), m->covariance(r, c), 0.02 * scale) << r << "," << c;
    }
  }
}

}  // namespace
}  // namespace dslam
