#include <random>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>

#include "dslam/core/camera.h"

namespace dslam {
namespace {

PinholeCamera BonnLikeCamera() {
  Distortion d;
  d.k1 = 0.039903;
  d.k2 = -0.099343;
  d.p1 = -0.000730;
  d.p2 = -0.000144;
  return PinholeCamera(640, 480, 542.8, 542.6, 315.6, 237.8, d);
}

TEST(PinholeCamera, ProjectInvertsBackProject) {
  const PinholeCamera camera(640, 480, 525.0, 525.0, 319.5, 239.5);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, 639.0), v(0.0, 479.0), z(0.3, 8.0);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector2d uv(u(rng), v(rng));
    const Eigen::Vector3d p = camera.BackProject(uv, z(rng));
    EXPECT_NEAR((camera.Project(p) - uv).norm(), 0.0, 1e-9);
  }
}

TEST(PinholeCamera, BackProjectMatchesPaperMeasurementModel) {
  const PinholeCamera camera(640, 480, 500.0, 400.0, 320.0, 240.0);
  const Eigen::Vector3d y = camera.BackProject(Eigen::Vector2d(420.0, 140.0), 2.0);
  EXPECT_DOUBLE_EQ(y.x(), 100.0 * 2.0 / 500.0);
  EXPECT_DOUBLE_EQ(y.y(), -100.0 * 2.0 / 400.0);
  EXPECT_DOUBLE_EQ(y.z(), 2.0);
}

TEST(PinholeCamera, UndistortInvertsDistort) {
  const PinholeCamera camera = BonnLikeCamera();
  for (double u = 0; u < 640; u += 37) {
    for (double v = 0; v < 480; v += 29) {
      const Eigen::Vector2d ideal(u, v);
      EXPECT_NEAR((camera.Undistort(camera.Distort(ideal)) - ideal).norm(), 0.0, 1e-6);
    }
  }
}

// The fixed-point iteration Undistort implements, always run 20 times.
Eigen::Vector2d UndistortTwentyIterations(const PinholeCamera& camera, const Distortion& d,
                                          const Eigen::Vector2d& uv) {
  const double xd = (uv.x() - camera.cx()) / camera.fx();
  const double yd = (uv.y() - camera.cy()) / camera.fy();
  double x = xd, y = yd;
  for (int i = 0; i < 20; ++i) {
    const double r2 = x * x + y * y;
    const double radial = 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
    const double dx = 2.0 * d.p1 * x * y + d.p2 * (r2 + 2.0 * x * x);
    const double dy = d.p1 * (r2 + 2.0 * y * y) + 2.0 * d.p2 * x * y;
    x = (xd - dx) / radial;
    y = (yd - dy) / radial;
  }
  return {camera.fx() * x + camera.cx(), camera.fy() * y + camera.cy()};
}

TEST(PinholeCamera, UndistortStopsAtAFixedPointWithTheSameResult) {
  Distortion strong;
  strong.k1 = -0.28;
  strong.k2 = 0.07;
  strong.p1 = 0.001;
  strong.p2 = -0.0012;
  strong.k3 = 0.01;
  const Distortion bonn = BonnLikeCamera().distortion();
  for (const Distortion& d : {bonn, strong}) {
    const PinholeCamera camera(640, 480, 542.8, 542.6, 315.6, 237.8, d);
    for (double u = 0.0; u < 640.0; u += 7.3) {
      for (double v = 0.0; v < 480.0; v += 5.9) {
        const Eigen::Vector2d uv(u, v);
        const Eigen::Vector2d expected = UndistortTwentyIterations(camera, d, uv);
        const Eigen::Vector2d got = camera.Undistort(uv);
        ASSERT_EQ(got.x(), expected.x()) << u << " " << v;
        ASSERT_EQ(got.y(), expected.y()) << u << " " << v;
      }
    }
  }
}

TEST(PinholeCamera, DistortionMovesCornersNotCentre) {
  const PinholeCamera camera = BonnLikeCamera();
  const Eigen::Vector2d centre(camera.cx(), camera.cy());
  EXPECT_NEAR((camera.Distort(centre) - centre).norm(), 0.0, 1e-12);
  EXPECT_GT((camera.Distort(Eigen::Vector2d(0, 0)) - Eigen::Vector2d(0, 0)).norm(), 0.5);
}

TEST(PinholeCamera, RejectsInvalidIntrinsics) {
  EXPECT_THROW(PinholeCamera(0, 480, 500, 500, 320, 240), std::invalid_argument);
  EXPECT_THROW(PinholeCamera(640, 480, -1, 500, 320, 240), std::invalid_argument);
}

TEST(PinholeCamera, InImageHonoursBorder) {
  const PinholeCamera camera(640, 480, 525.0, 525.0, 319.5, 239.5);
  EXPECT_TRUE(camera.InImage(Eigen::Vector2d(0, 0)));
  EXPECT_FALSE(camera.InImage(Eigen::Vector2d(0, 0), 1.0));
  EXPECT_FALSE(camera.InImage(Eigen::Vector2d(639.5, 10)));
}

// Distort and Undistort against OpenCV's own model (cv::projectPoints and cv::undistortPoints
// with the same plumb_bob coefficients): a sign or a swapped coefficient shared by both would
// pass the round trip above but not this. Coefficients of TUM freiburg1 (strong) and Bonn.
TEST(PinholeCamera, DistortAndUndistortAgreeWithOpenCv) {
  const std::vector<Distortion> models = {{0.2624, -0.9531, -0.0054, 0.0026, 1.1633},
                                          {0.039903, -0.099343, -0.000730, -0.000144, 0.0}};
  for (const Distortion& d : models) {
    const PinholeCamera camera(640, 480, 517.3, 516.5, 318.6, 255.3, d);
    const cv::Matx33d K(517.3, 0.0, 318.6, 0.0, 516.5, 255.3, 0.0, 0.0, 1.0);
    const std::vector<double> coefficients = {d.k1, d.k2, d.p1, d.p2, d.k3};
    for (double u = 20; u < 640; u += 61) {
      for (double v = 20; v < 480; v += 47) {
        // Ideal pixel -> a point on the ray -> OpenCV's distorted pixel.
        const Eigen::Vector3d ray = camera.BackProject(Eigen::Vector2d(u, v), 1.0);
        std::vector<cv::Point2d> projected;
        cv::projectPoints(std::vector<cv::Point3d>{{ray.x(), ray.y(), ray.z()}}, cv::Vec3d(0, 0, 0),
                          cv::Vec3d(0, 0, 0), K, coefficients, projected);
        const Eigen::Vector2d distorted = camera.Distort(Eigen::Vector2d(u, v));
        EXPECT_NEAR(distorted.x(), projected[0].x, 1e-6) << u << " " << v;
        EXPECT_NEAR(distorted.y(), projected[0].y, 1e-6) << u << " " << v;
        // OpenCV's inverse (its own iteration) back to the ideal pixel.
        std::vector<cv::Point2d> undistorted;
        cv::undistortPoints(
            projected, undistorted, K, coefficients, cv::noArray(), K,
            cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 200, 1e-14));
        const Eigen::Vector2d ours = camera.Undistort(distorted);
        EXPECT_NEAR(ours.x(), u, 1e-3);
        EXPECT_NEAR(ours.y(), v, 1e-3);
        EXPECT_NEAR(ours.x(), undistorted[0].x, 1e-3) << u << " " << v;
        EXPECT_NEAR(ours.y(), undistorted[0].y, 1e-3) << u << " " << v;
      }
    }
  }
}

}  // namespace
}  // namespace dslam
