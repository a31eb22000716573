// The hand-written Levenberg-Marquardt pose solver (PoseSolver::kLevenbergMarquardt, what dslam
// runs) against the Ceres solve of the same cost (PoseSolver::kCeres, the reference) and against
// the known pose of seeded scenes.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "dslam/tracking/pose_optimizer.h"
#include "dslam/tracking/robust_pose.h"
#include "support/textured_frame.h"
#include "tracking/pose_scene.h"

namespace dslam {
namespace {

Eigen::Isometry3d Offset(const Eigen::Isometry3d& T, double metres, double radians) {
  return Eigen::Translation3d(metres * Eigen::Vector3d(0.6, -0.48, 0.64)) *
         Eigen::AngleAxisd(radians, Eigen::Vector3d(1.0, 0.5, -0.2).normalized()) * T;
}

double TranslationError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

double RotationErrorRad(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.rotation().transpose() * b.rotation()).angle();
}

// Both solvers from the same start: the same pose (1e-6 m, 1e-6 rad), the same classification.
void ExpectSameSolution(const PoseResult& lm, const PoseResult& ceres) {
  ASSERT_TRUE(lm.success);
  ASSERT_TRUE(ceres.success);
  EXPECT_LT(TranslationError(lm.T_camera_world, ceres.T_camera_world), 1e-6);
  EXPECT_LT(RotationErrorRad(lm.T_camera_world, ceres.T_camera_world), 1e-6);
  EXPECT_EQ(lm.inliers, ceres.inliers);
  EXPECT_EQ(lm.num_inliers, ceres.num_inliers);
  EXPECT_NEAR(lm.final_cost, ceres.final_cost, 1e-6 * ceres.final_cost);
  EXPECT_EQ(lm.iterations, ceres.iterations);  // the same steps, the same stopping
}

struct SceneCase {
  double outliers;       // fraction of gross outliers
  int pixel_only_every;  // every k-th observation without depth (0: none)
  double start_m;        // [m] start offset
  double start_rad;      // [rad] start offset
};

class PoseSolverTest : public ::testing::TestWithParam<SceneCase> {};

TEST_P(PoseSolverTest, MatchesCeresAndRecoversTruth) {
  const PinholeCamera camera = test::TestCamera();
  const SceneCase c = GetParam();
  for (unsigned seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const test::PoseScene scene =
        test::MakePoseScene(camera, 300, c.outliers, 100 + seed, c.pixel_only_every);
    const Eigen::Isometry3d start = Offset(scene.T_camera_world, c.start_m, c.start_rad);
    const PoseResult lm = EstimatePose(scene.observations, start, camera, PoseConfig());
    const PoseResult ceres =
        EstimatePose(scene.observations, start, camera, PoseConfig(), nullptr, PoseSolver::kCeres);
    ExpectSameSolution(lm, ceres);
    EXPECT_LT(TranslationError(lm.T_camera_world, scene.T_camera_world), 0.005);
    EXPECT_LT(RotationErrorRad(lm.T_camera_world, scene.T_camera_world), 0.2 * M_PI / 180.0);
    int missed_outliers = 0, lost_inliers = 0, inliers = 0;
    for (size_t i = 0; i < scene.observations.size(); ++i) {
      missed_outliers += scene.is_outlier[i] && lm.inliers[i];
      lost_inliers += !scene.is_outlier[i] && !lm.inliers[i];
      inliers += !scene.is_outlier[i];
    }
    EXPECT_EQ(missed_outliers, 0);
    EXPECT_LT(lost_inliers, 0.1 * inliers);  // chi2 95%: about 5% of true inliers fall outside
  }
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, PoseSolverTest,
    ::testing::Values(SceneCase{0.0, 0, 0.05, 0.05}, SceneCase{0.0, 3, 0.05, 0.05},
                      SceneCase{0.2, 0, 0.05, 0.05}, SceneCase{0.3, 4, 0.05, 0.05},
                      SceneCase{0.4, 0, 0.03, 0.03}, SceneCase{0.0, 0, 0.3, 0.2}));

// Without noise and outliers the solution is the true pose.
TEST(PoseSolver, ExactDataGivesTruePose) {
  const PinholeCamera camera = test::TestCamera();
  test::PoseScene scene = test::MakePoseScene(camera, 100, 0.0, 7, 3);
  for (PoseObservation& o : scene.observations) {
    const Eigen::Vector3d p = scene.T_camera_world * o.p_world;
    o.y_camera = p;
    o.uv_ideal = camera.Project(p);
  }
  const PoseResult r = EstimatePose(scene.observations, Offset(scene.T_camera_world, 0.05, 0.05),
                                    camera, PoseConfig());
  ASSERT_TRUE(r.success);
  EXPECT_LT(TranslationError(r.T_camera_world, scene.T_camera_world), 1e-9);
  EXPECT_LT(RotationErrorRad(r.T_camera_world, scene.T_camera_world), 1e-9);
  EXPECT_EQ(r.num_inliers, 100);
}

// One round over all observations: final_cost is 1/2 sum of Huber rho(s) of the squared whitened
// errors at the returned pose, s <= d^2: s, else 2 d sqrt(s) - d^2.
TEST(PoseSolver, FinalCostIsTheHuberCost) {
  const PinholeCamera camera = test::TestCamera();
  const test::PoseScene scene = test::MakePoseScene(camera, 200, 0.3, 8, 4);
  PoseConfig config;
  config.rounds = 1;
  const PoseResult r =
      EstimatePose(scene.observations, Offset(scene.T_camera_world, 0.05, 0.05), camera, config);
  ASSERT_TRUE(r.success);
  double cost = 0.0;
  for (const PoseObservation& o : scene.observations) {
    const double s = SquaredError(o, r.T_camera_world, camera);
    const double d = o.has_depth ? config.huber_delta_depth : config.huber_delta_pixel;
    cost += 0.5 * (s <= d * d ? s : 2.0 * d * std::sqrt(s) - d * d);
  }
  EXPECT_NEAR(r.final_cost, cost, 1e-9 * cost);
}

// The iteration limit and the iteration count follow Ceres: with 1-3 iterations per round both
// stop at the same pose after the same number of iterations (including failures: one step from
// this start leaves fewer than 3 inliers).
TEST(PoseSolver, IterationLimitMatchesCeres) {
  const PinholeCamera camera = test::TestCamera();
  const test::PoseScene scene = test::MakePoseScene(camera, 200, 0.2, 9, 5);
  const Eigen::Isometry3d start = Offset(scene.T_camera_world, 0.05, 0.05);
  for (int max_iterations = 1; max_iterations <= 3; ++max_iterations) {
    SCOPED_TRACE("max_iterations " + std::to_string(max_iterations));
    PoseConfig config;
    config.max_iterations = max_iterations;
    const PoseResult lm = EstimatePose(scene.observations, start, camera, config);
    const PoseResult ceres =
        EstimatePose(scene.observations, start, camera, config, nullptr, PoseSolver::kCeres);
    EXPECT_EQ(lm.success, ceres.success);
    EXPECT_EQ(lm.iterations, ceres.iterations);
    EXPECT_EQ(lm.num_inliers, ceres.num_inliers);
    EXPECT_LT(TranslationError(lm.T_camera_world, ceres.T_camera_world), 1e-6);
    EXPECT_LT(RotationErrorRad(lm.T_camera_world, ceres.T_camera_world), 1e-6);
    EXPECT_NEAR(lm.final_cost, ceres.final_cost, 1e-6 * ceres.final_cost);
  }
}

// RANSAC then BA (the front end's initial pose) gives the same result with either solver.
TEST(PoseSolver, RobustPoseMatchesCeres) {
  const PinholeCamera camera = test::TestCamera();
  for (unsigned seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const test::PoseScene scene = test::MakePoseScene(camera, 300, 0.4, 200 + seed, 5);
    const PoseResult lm = EstimatePoseRobust(scene.observations, camera, PoseConfig(), seed);
    const PoseResult ceres =
        EstimatePoseRobust(scene.observations, camera, PoseConfig(), seed, PoseSolver::kCeres);
    ExpectSameSolution(lm, ceres);
    EXPECT_LT(TranslationError(lm.T_camera_world, scene.T_camera_world), 0.005);
  }
}

}  // namespace
}  // namespace dslam
