#include <random>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace dslam
