#include <random>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "dslam/eval/groundtruth_correction.h"

namespace dslam {
namespace {

bool IsProperRotation(const Eigen::Matrix3d& r) {
  return (r.transpose() * r).isApprox(Eigen::Matrix3d::Identity(), 1e-12) &&
         std::abs(r.determinant() - 1.0) < 1e-12;
}

TEST(GroundTruthCorrection, AxisChangeIsAnInvolutiveRotation) {
  const Eigen::Matrix4d t_ros = BonnAxisChange();
  const Eigen::Matrix3d s = t_ros.topLeftCorner<3, 3>();
  // Not a reflection (det +1): a half turn about (0, 1, 1)/sqrt(2).
  EXPECT_TRUE(IsProperRotation(s));
  EXPECT_NEAR(Eigen::AngleAxisd(s).angle(), M_PI, 1e-12);
  EXPECT_TRUE((s * Eigen::Vector3d(0, 1, 1)).isApprox(Eigen::Vector3d(0, 1, 1)));
  EXPECT_TRUE((t_ros * t_ros).isApprox(Eigen::Matrix4d::Identity()));
}

TEST(GroundTruthCorrection, MarkerOffsetIsTheNearestRotation) {
  const Eigen::Matrix3d raw = BonnMarkerToCameraRaw().topLeftCorner<3, 3>();
  EXPECT_FALSE(IsProperRotation(raw));
  const Eigen::Isometry3d t_m = BonnMarkerToCamera();
  const Eigen::Matrix3d r = t_m.linear();
  EXPECT_TRUE(IsProperRotation(r));
  // The Frobenius-nearest rotation R of M is the one with R^T M symmetric positive definite.
  const Eigen::Matrix3d s = r.transpose() * raw;
  EXPECT_TRUE(s.isApprox(s.transpose(), 1e-12));
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(s).eigenvalues().minCoeff(), 0.0);
  // Values computed by hand (numpy SVD) from the published matrix.
  Eigen::Matrix3d expected;
  expected << 0.95881915, 0.17259353, -0.22555999,  //
      0.00084455, -0.79590598, -0.60541966,         //
      -0.28401606, 0.58029747, -0.76327565;
  EXPECT_TRUE(r.isApprox(expected, 1e-7)) << r;
  EXPECT_TRUE(t_m.translation().isApprox(Eigen::Vector3d(0.0113, -0.0098, 0.0111)));
}

TEST(GroundTruthCorrection, IdentityMarkerPoseGivesTheMarkerOffset) {
  const Eigen::Isometry3d camera = BonnCameraPose(Eigen::Isometry3d::Identity());
  EXPECT_TRUE(camera.isApprox(BonnMarkerToCamera(), 1e-12));
}

TEST(GroundTruthCorrection, MatchesHandComputedPose) {
  // Marker pose: 90 deg about z, translation (1, 2, 3).
  Eigen::Isometry3d T_world_marker = Eigen::Isometry3d::Identity();
  T_world_marker.linear() =
      Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T_world_marker.translation() = Eigen::Vector3d(1, 2, 3);
  // By hand: T_ros R_z(90) T_ros = R_y(90) = [[0,0,1],[0,1,0],[-1,0,0]], T_ros t = (-1, 3, 2);
  // camera translation = R_y(90) t_m + (-1, 3, 2) with t_m = (0.0113, -0.0098, 0.0111).
  const Eigen::Isometry3d camera = BonnCameraPose(T_world_marker);
  EXPECT_TRUE(camera.translation().isApprox(Eigen::Vector3d(-0.9889, 2.9902, 1.9887), 1e-12))
      << camera.translation().transpose();
  Eigen::Matrix3d expected_rotation;  // R_y(90) * nearest rotation of T_m (rows permuted, signed)
  expected_rotation << -0.28401606, 0.58029747, -0.76327565,  //
      0.00084455, -0.79590598, -0.60541966,                   //
      -0.95881915, -0.17259353, 0.22555999;
  EXPECT_TRUE(camera.linear().isApprox(expected_rotation, 1e-7)) << camera.linear();
}

TEST(GroundTruthCorrection, CorrectedTrajectoryHasProperRigidPoses) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Trajectory groundtruth;
  for (int i = 0; i < 50; ++i) {
    StampedPose pose;
    pose.stamp_s = 100.0 + i / 30.0;
    pose.T_world_camera.linear() =
        Eigen::Quaterniond(uniform(rng), uniform(rng), uniform(rng), uniform(rng))
            .normalized()
            .toRotationMatrix();
    pose.T_world_camera.translation() = Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng));
    groundtruth.push_back(pose);
  }
  const Trajectory corrected =
      ApplyGroundTruthCorrection(groundtruth, GroundTruthCorrection::kBonn);
  ASSERT_EQ(corrected.size(), groundtruth.size());
  for (size_t i = 0; i < corrected.size(); ++i) {
    EXPECT_DOUBLE_EQ(corrected[i].stamp_s, groundtruth[i].stamp_s);
    EXPECT_TRUE(IsProperRotation(corrected[i].T_world_camera.linear()));
    EXPECT_TRUE(
        corrected[i].T_world_camera.matrix().row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1)));
  }
  // The correction preserves relative motion magnitudes up to the fixed offset: distances between
  // camera centres differ from marker distances by at most 2 |t_m|.
  const double offset = BonnMarkerToCamera().translation().norm();
  const double d_marker =
      (groundtruth[0].T_world_camera.translation() - groundtruth[1].T_world_camera.translation())
          .norm();
  const double d_camera =
      (corrected[0].T_world_camera.translation() - corrected[1].T_world_camera.translation())
          .norm();
  EXPECT_LE(std::abs(d_marker - d_camera), 2 * offset + 1e-12);
  const Trajectory unchanged =
      ApplyGroundTruthCorrection(groundtruth, GroundTruthCorrection::kNone);
  EXPECT_TRUE(unchanged[3].T_world_camera.isApprox(groundtruth[3].T_world_camera));
}

}  // namespace
}  // namespace dslam
