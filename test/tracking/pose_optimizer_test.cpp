#include "dslam/tracking/pose_optimizer.h"

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "support/textured_frame.h"
#include "tracking/pose_scene.h"

namespace dslam {
namespace {

Eigen::Isometry3d Perturb(const Eigen::Isometry3d& T) {
  return Eigen::Translation3d(0.04, -0.03, 0.05) *
         Eigen::AngleAxisd(0.05, Eigen::Vector3d(1.0, 0.5, -0.2).normalized()) * T;
}

TEST(PoseOptimizer, RotatedPointJacobianMatchesFiniteDifferences) {
  const Eigen::Vector3d p(0.7, -1.2, 2.5);
  // A unit quaternion and a non-unit one (the solver's parameters between manifold steps).
  for (const Eigen::Quaterniond& q :
       {Eigen::Quaterniond(Eigen::AngleAxisd(0.8, Eigen::Vector3d(1.0, -2.0, 0.5).normalized())),
        Eigen::Quaterniond(1.1, 0.2, -0.3, 0.4)}) {
    const Eigen::Matrix<double, 3, 4> J = RotatedPointByQuaternion(q, p);
    const double h = 1e-7;
    for (int k = 0; k < 4; ++k) {
      Eigen::Quaterniond plus = q, minus = q;
      plus.coeffs()[k] += h;
      minus.coeffs()[k] -= h;
      const Eigen::Vector3d numeric = (plus * p - minus * p) / (2.0 * h);
      EXPECT_LT((J.col(k) - numeric).norm(), 1e-6) << "coefficient " << k;
    }
  }
}

TEST(PoseOptimizer, RecoversPoseAndFlagsOutliers) {
  const PinholeCamera camera = test::TestCamera();
  const test::PoseScene scene = test::MakePoseScene(camera, 200, 0.3, 11);
  const PoseResult r =
      EstimatePose(scene.observations, Perturb(scene.T_camera_world), camera, PoseConfig());
  ASSERT_TRUE(r.success);
  EXPECT_LT((r.T_camera_world.translation() - scene.T_camera_world.translation()).norm(), 0.005);
  EXPECT_LT(test::RotationErrorDeg(r.T_camera_world, scene.T_camera_world), 0.2);
  int missed_outliers = 0, lost_inliers = 0, inliers = 0;
  for (size_t i = 0; i < scene.observations.size(); ++i) {
    missed_outliers += scene.is_outlier[i] && r.inliers[i];
    lost_inliers += !scene.is_outlier[i] && !r.inliers[i];
    inliers += !scene.is_outlier[i];
  }
  EXPECT_EQ(missed_outliers, 0);
  EXPECT_LT(lost_inliers, 0.1 * inliers);  // chi2 95%: about 5% of true inliers fall outside
  EXPECT_GT(r.iterations, 0);
  EXPECT_GT(r.final_cost, 0.0);
}

// The fit of the model that the status reports (pose_chi2_per_dof, pose_observations): noise drawn
// from the observations' own covariances gives the truncated chi-square mean, about 0.88 per dof
// for 3 dof at the 95 % bound; a model three times too tight in every sigma gates most of them out.
TEST(PoseOptimizer, ReportsTheFitOfTheMeasurementModel) {
  const PinholeCamera camera = test::TestCamera();
  const test::PoseScene scene = test::MakePoseScene(camera, 300, 0.0, 21);
  const PoseResult fits =
      EstimatePose(scene.observations, Perturb(scene.T_camera_world), camera, PoseConfig());
  ASSERT_TRUE(fits.success);
  EXPECT_EQ(fits.num_observations, 300);
  EXPECT_GT(fits.inlier_chi2_per_dof, 0.75);
  EXPECT_LT(fits.inlier_chi2_per_dof, 1.0);
  EXPECT_LT(1.0 - static_cast<double>(fits.num_inliers) / fits.num_observations, 0.10);

  std::vector<PoseObservation> too_tight = scene.observations;
  for (PoseObservation& o : too_tight) o.covariance /= 9.0;
  const PoseResult tight =
      EstimatePose(too_tight, Perturb(scene.T_camera_world), camera, PoseConfig());
  ASSERT_TRUE(tight.success);
  EXPECT_GT(1.0 - static_cast<double>(tight.num_inliers) / tight.num_observations, 0.5);
}

TEST(PoseOptimizer, MixesPixelOnlyObservations) {
  const PinholeCamera camera = test::TestCamera();
  const test::PoseScene scene = test::MakePoseScene(camera, 200, 0.2, 12, 3);
  const PoseResult r =
      EstimatePose(scene.observations, Perturb(scene.T_camera_world), camera, PoseConfig());
  ASSERT_TRUE(r.success);
  EXPECT_LT((r.T_camera_world.translation() - scene.T_camera_world.translation()).norm(), 0.005);
  EXPECT_LT(test::RotationErrorDeg(r.T_camera_world, scene.T_camera_world), 0.2);
  for (size_t i = 0; i < scene.observations.size(); ++i) {
    if (scene.is_outlier[i]) {
      EXPECT_FALSE(r.inliers[i]) << i;
    }
  }
}

TEST(PoseOptimizer, InformationIsSpdAndMatchesCovarianceConversion) {
  const PinholeCamera camera = test::TestCamera();
  const test::PoseScene scene = test::MakePoseScene(camera, 100, 0.0, 13, 4);
  const PoseResult r = EstimatePose(scene.observations, scene.T_camera_world, camera, PoseConfig());
  ASSERT_TRUE(r.success);
  EXPECT_LT((r.information - r.information.transpose()).norm(), 1e-9 * r.information.norm());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(r.information);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
  const Eigen::Matrix<double, 6, 6> cov = CovarianceWorldCamera(r);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig_cov(cov);
  EXPECT_GT(eig_cov.eigenvalues().minCoeff(), 0.0);
  EXPECT_LT(std::sqrt(cov(0, 0)), 0.01);  // [m] 100 points at 1-4 m: millimetre-level position
}

// The perturbation mapping agrees with finite differences of T_world_camera.
TEST(PoseOptimizer, PerturbationMappingMatchesFiniteDifferences) {
  const PinholeCamera camera = test::TestCamera();
  const Eigen::Isometry3d T_cw = test::MakePoseScene(camera, 1, 0.0, 1).T_camera_world;
  const Eigen::Matrix<double, 6, 6> A = PerturbationToWorldCamera(T_cw);
  const double h = 1e-6;
  for (int k = 0; k < 6; ++k) {
    Eigen::Matrix<double, 6, 1> delta = Eigen::Matrix<double, 6, 1>::Zero();
    delta(k) = h;
    Eigen::Isometry3d T = T_cw;  // (Exp(dtheta) R_cw, t_cw + dt)
    if (k < 3) T.linear() = Eigen::AngleAxisd(h, Eigen::Vector3d::Unit(k)) * T_cw.rotation();
    T.translation() = T_cw.translation() + delta.tail<3>();
    const Eigen::Isometry3d W0 = T_cw.inverse(), W1 = T.inverse();
    Eigen::Matrix<double, 6, 1> numeric;
    numeric.head<3>() = (W1.translation() - W0.translation()) / h;
    const Eigen::AngleAxisd dR(W1.rotation() * W0.rotation().transpose());
    numeric.tail<3>() = dR.axis() * dR.angle() / h;
    EXPECT_LT((numeric - A.col(k)).norm(), 1e-4) << "column " << k;
  }
}

// Information of the inlier residuals at T_cw, J^T W J, with J by central differences of the
// residuals under the perturbation `perturb(T_cw, delta)` (delta in R^6).
template <typename Perturb>
Eigen::Matrix<double, 6, 6> NumericInformation(const test::PoseScene& scene,
                                               const std::vector<bool>& inliers,
                                               const Eigen::Isometry3d& T_cw,
                                               const PinholeCamera& camera, Perturb perturb) {
  const double h = 1e-6;
  auto residual = [&](const PoseObservation& o, const Eigen::Isometry3d& T) -> Eigen::Vector3d {
    const Eigen::Vector3d p = T * o.p_world;
    if (o.has_depth) return p - o.y_camera;
    const Eigen::Vector2d e = (camera.Project(p) - o.uv_ideal) / o.pixel_sigma_px;
    return Eigen::Vector3d(e.x(), e.y(), 0.0);
  };
  Eigen::Matrix<double, 6, 6> information = Eigen::Matrix<double, 6, 6>::Zero();
  for (size_t i = 0; i < scene.observations.size(); ++i) {
    if (!inliers[i]) continue;
    const PoseObservation& o = scene.observations[i];
    Eigen::Matrix<double, 3, 6> J;
    for (int k = 0; k < 6; ++k) {
      Eigen::Matrix<double, 6, 1> delta = Eigen::Matrix<double, 6, 1>::Zero();
      delta(k) = h;
      J.col(k) = (residual(o, perturb(T_cw, delta)) - residual(o, perturb(T_cw, -delta))) / (2 * h);
    }
    const Eigen::Matrix3d W = o.has_depth ? Eigen::Matrix3d(o.covariance.inverse())
                                          : Eigen::Matrix3d(Eigen::Vector3d(1, 1, 0).asDiagonal());
    information += J.transpose() * W * J;
  }
  return information;
}

// PoseResult::information is J^T J of the perturbation (Exp(dtheta) R_cw, t_cw + dt) that the
// solvers use, also for a camera away from the world origin.
TEST(PoseOptimizer, InformationMatchesFiniteDifferences) {
  const PinholeCamera camera = test::TestCamera();
  const test::PoseScene scene = test::MakePoseScene(camera, 60, 0.0, 15, 5);
  ASSERT_GT(scene.T_camera_world.translation().norm(), 1.0);
  const PoseResult r = EstimatePose(scene.observations, scene.T_camera_world, camera, PoseConfig());
  ASSERT_TRUE(r.success);
  auto left = [](const Eigen::Isometry3d& T, const Eigen::Matrix<double, 6, 1>& d) {
    Eigen::Isometry3d P = T;
    P.linear() =
        Eigen::AngleAxisd(d.head<3>().norm(), d.head<3>().normalized()).matrix() * T.rotation();
    P.translation() = T.translation() + d.tail<3>();
    return P;
  };
  const Eigen::Matrix<double, 6, 6> numeric =
      NumericInformation(scene, r.inliers, r.T_camera_world, camera, left);
  EXPECT_LT((numeric - r.information).norm(), 1e-5 * numeric.norm())
      << "analytic\n"
      << r.information << "\nnumeric\n"
      << numeric;
}

// CovarianceWorldCamera() is the inverse information of T_world_camera in ROS order
// [x y z rx ry rz] (rotation about the fixed world axes), from finite differences.
TEST(PoseOptimizer, CovarianceMatchesFiniteDifferences) {
  const PinholeCamera camera = test::TestCamera();
  const test::PoseScene scene = test::MakePoseScene(camera, 60, 0.0, 16, 5);
  const PoseResult r = EstimatePose(scene.observations, scene.T_camera_world, camera, PoseConfig());
  ASSERT_TRUE(r.success);
  auto world = [](const Eigen::Isometry3d& T_cw, const Eigen::Matrix<double, 6, 1>& d) {
    const Eigen::Isometry3d T_wc = T_cw.inverse();
    Eigen::Isometry3d P = T_wc;
    P.linear() =
        Eigen::AngleAxisd(d.tail<3>().norm(), d.tail<3>().normalized()).matrix() * T_wc.rotation();
    P.translation() = T_wc.translation() + d.head<3>();
    return Eigen::Isometry3d(P.inverse());
  };
  const Eigen::Matrix<double, 6, 6> numeric =
      NumericInformation(scene, r.inliers, r.T_camera_world, camera, world)
          .ldlt()
          .solve(Eigen::Matrix<double, 6, 6>::Identity());
  const Eigen::Matrix<double, 6, 6> covariance = CovarianceWorldCamera(r);
  EXPECT_LT((numeric - covariance).norm(), 1e-4 * numeric.norm()) << "analytic\n"
                                                                  << covariance << "\nnumeric\n"
                                                                  << numeric;
}

TEST(PoseOptimizer, FailsWithTooFewObservations) {
  const PinholeCamera camera = test::TestCamera();
  const test::PoseScene scene = test::MakePoseScene(camera, 2, 0.0, 14);
  EXPECT_FALSE(
      EstimatePose(scene.observations, scene.T_camera_world, camera, PoseConfig()).success);
}

}  // namespace
}  // namespace dslam
