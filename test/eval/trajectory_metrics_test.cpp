#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "dslam/eval/trajectory_metrics.h"

namespace dslam {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

StampedPose MakePose(double stamp_s, const Eigen::Matrix3d& rotation,
                     const Eigen::Vector3d& position) {
  StampedPose pose;
  pose.stamp_s = stamp_s;
  pose.T_world_camera.linear() = rotation;
  pose.T_world_camera.translation() = position;
  return pose;
}

// ~30 Hz stamps over ~10 s with +-5 ms seeded jitter.
std::vector<double> JitteredStamps(int count) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> jitter(-0.005, 0.005);
  std::vector<double> stamps;
  for (int i = 0; i < count; ++i) stamps.push_back(1000.0 + i / 30.0 + jitter(rng));
  return stamps;
}

// A helix with a turning camera: a trajectory whose positions span all three dimensions.
StampedPose HelixPose(double stamp_s, double t) {
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(0.3 * t, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(0.1 * t, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  return MakePose(stamp_s, rotation,
                  Eigen::Vector3d(std::cos(0.5 * t), std::sin(0.5 * t), 0.1 * t));
}

Eigen::Isometry3d SomeRigidTransform() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() =
      Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -1.0, 0.5).normalized()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(2.0, -0.5, 1.5);
  return T;
}

// The estimate expressed in another world frame: T_estworld_gtworld * T_gtworld_camera.
Trajectory MoveWorld(const Trajectory& trajectory, const Eigen::Isometry3d& T_new_old) {
  Trajectory moved = trajectory;
  for (StampedPose& pose : moved) pose.T_world_camera = T_new_old * pose.T_world_camera;
  return moved;
}

TEST(TrajectoryMetrics, RigidlyMovedGroundTruthHasZeroError) {
  Trajectory groundtruth;
  for (double s : JitteredStamps(300)) groundtruth.push_back(HelixPose(s, s - 1000.0));
  const Eigen::Isometry3d T_est_gt = SomeRigidTransform();
  const TrajectoryMetrics m =
      EvaluateTrajectory(MoveWorld(groundtruth, T_est_gt), groundtruth, {}, {});
  EXPECT_EQ(m.num_associated, 300u);
  EXPECT_NEAR(m.ate_m.rmse, 0.0, 1e-9);
  EXPECT_NEAR(m.ate_m.max, 0.0, 1e-9);
  EXPECT_NEAR(m.rpe.translation_rmse_m_per_s, 0.0, 1e-9);
  EXPECT_NEAR(m.rpe.rotation_rmse_deg_per_s, 0.0, 1e-6);
  EXPECT_GT(m.rpe.num_pairs, 250u);
  EXPECT_TRUE(m.T_gtworld_estworld.isApprox(T_est_gt.inverse(), 1e-9));
  EXPECT_DOUBLE_EQ(m.coverage.fraction, 1.0);
}

TEST(TrajectoryMetrics, KnownOffsetsGiveKnownAte) {
  // Positions held for two frames; the two get opposite offsets +-a_m u, a_m = 1, 2, 3 cm. Offsets
  // have zero mean and no correlation with the positions, so the optimal alignment is the true one
  // and every residual is a_m: RMSE = 0.01 sqrt(14/3), mean = median = 0.02, max = 0.03.
  const Eigen::Vector3d u = Eigen::Vector3d(1.0, 2.0, -1.0).normalized();
  Trajectory groundtruth, estimated;
  for (int k = 0; k < 120; ++k) {
    const int m = k / 2;
    const StampedPose gt = HelixPose(k / 30.0, m * 0.2);
    groundtruth.push_back(gt);
    StampedPose est = gt;
    est.T_world_camera.translation() += (k % 2 == 0 ? 1.0 : -1.0) * 0.01 * (1 + m % 3) * u;
    estimated.push_back(est);
  }
  const Eigen::Isometry3d T_est_gt = SomeRigidTransform();
  const TrajectoryMetrics m =
      EvaluateTrajectory(MoveWorld(estimated, T_est_gt), groundtruth, {}, {});
  EXPECT_NEAR(m.ate_m.rmse, 0.01 * std::sqrt(14.0 / 3.0), 1e-9);
  EXPECT_NEAR(m.ate_m.mean, 0.02, 1e-9);
  EXPECT_NEAR(m.ate_m.median, 0.02, 1e-9);
  EXPECT_NEAR(m.ate_m.max, 0.03, 1e-9);
  EXPECT_TRUE(m.T_gtworld_estworld.isApprox(T_est_gt.inverse(), 1e-9));
}

TEST(TrajectoryMetrics, VelocityDriftGivesKnownTranslationalRpe) {
  // Ground truth moves at 0.5 m/s along x, the estimate at 0.53 m/s: 0.03 m/s for every pair,
  // whatever the pair's actual (jittered) interval.
  const Eigen::Matrix3d r0 = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 1, 0).normalized()).matrix();
  Trajectory groundtruth, estimated;
  for (double s : JitteredStamps(300)) {
    const double t = s - 1000.0;
    groundtruth.push_back(MakePose(s, r0, Eigen::Vector3d(0.5 * t, 0, 0)));
    estimated.push_back(MakePose(s, r0, Eigen::Vector3d(0.53 * t, 0, 0)));
  }
  const RelativePoseError rpe = ComputeRelativePoseError(
      AssociatePoses(MoveWorld(estimated, SomeRigidTransform()), groundtruth, 0.02), {});
  EXPECT_GT(rpe.num_pairs, 250u);
  EXPECT_NEAR(rpe.translation_rmse_m_per_s, 0.03, 1e-9);
  EXPECT_NEAR(rpe.rotation_rmse_deg_per_s, 0.0, 1e-6);
}

TEST(TrajectoryMetrics, RotationRateDriftGivesKnownRotationalRpe) {
  // Ground truth turns at 10 deg/s about z, the estimate at 12 deg/s: 2 deg/s.
  Trajectory groundtruth, estimated;
  const Eigen::Vector3d position(0.3, -0.2, 1.0);
  for (double s : JitteredStamps(300)) {
    const double t = s - 1000.0;
    const auto rz = [](double deg) {
      return Eigen::AngleAxisd(deg * kDegToRad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    };
    groundtruth.push_back(MakePose(s, rz(10.0 * t), position));
    estimated.push_back(MakePose(s, rz(12.0 * t), position));
  }
  const RelativePoseError rpe = ComputeRelativePoseError(
      AssociatePoses(MoveWorld(estimated, SomeRigidTransform()), groundtruth, 0.02), {});
  EXPECT_NEAR(rpe.rotation_rmse_deg_per_s, 2.0, 1e-7);
  EXPECT_NEAR(rpe.translation_rmse_m_per_s, 0.0, 1e-9);
}

TEST(TrajectoryMetrics, RpeSkipsPairsAcrossLongGaps) {
  // Stamps every 0.125 s (exact in binary), none for k = 41..59.
  Trajectory groundtruth;
  for (int k = 0; k < 100; ++k) {
    if (k > 40 && k < 60) continue;
    groundtruth.push_back(
        MakePose(0.125 * k, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()));
  }
  const PoseAssociation association{groundtruth, groundtruth};
  const RelativePoseError rpe = ComputeRelativePoseError(association, {});
  // Pairs k -> k + 8 (1 s) for k = 0..32 and 60..91; k = 33..40 would end at k = 60 (>= 2.5 s).
  EXPECT_EQ(rpe.num_pairs, 33u + 32u);
}

TEST(TrajectoryMetrics, AssociationIsNearestWithinToleranceAndUnique) {
  Trajectory groundtruth = {MakePose(1.0, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()),
                            MakePose(2.0, Eigen::Matrix3d::Identity(), Eigen::Vector3d::UnitX())};
  Trajectory estimated = {MakePose(2.0, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()),
                          MakePose(0.99, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()),
                          MakePose(1.005, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()),
                          MakePose(3.5, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero())};
  const PoseAssociation a = AssociatePoses(estimated, groundtruth, 0.02);
  ASSERT_EQ(a.estimated.size(), 2u);
  EXPECT_DOUBLE_EQ(a.estimated[0].stamp_s, 1.005);  // nearer than 0.99; gt 1.0 used once
  EXPECT_DOUBLE_EQ(a.groundtruth[0].stamp_s, 1.0);
  EXPECT_DOUBLE_EQ(a.estimated[1].stamp_s, 2.0);
  EXPECT_DOUBLE_EQ(a.groundtruth[1].stamp_s, 2.0);
  EXPECT_EQ(AssociatePoses(estimated, groundtruth, 0.004).estimated.size(), 1u);
  for (StampedPose& pose : estimated) pose.stamp_s += 0.5;
  EXPECT_THROW(EvaluateTrajectory(estimated, groundtruth, {}, {}), std::runtime_error);
}

TEST(TrajectoryMetrics, UmeyamaRecoversKnownTransform) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(-2.0, 2.0);
  const Eigen::Isometry3d T = SomeRigidTransform();
  for (bool planar : {false, true}) {
    std::vector<Eigen::Vector3d> source, target;
    for (int k = 0; k < 40; ++k) {
      const Eigen::Vector3d p(uniform(rng), uniform(rng), planar ? 0.0 : uniform(rng));
      source.push_back(p);
      target.push_back(T * p);
    }
    const Eigen::Isometry3d estimated = AlignPositions(source, target);
    EXPECT_TRUE(estimated.isApprox(T, 1e-9)) << "planar " << planar;
    EXPECT_NEAR(estimated.linear().determinant(), 1.0, 1e-12);
  }
  EXPECT_THROW(AlignPositions({}, {}), std::invalid_argument);
}

TEST(TrajectoryMetrics, ErrorStatisticsOfKnownValues) {
  const ErrorStatistics s = ComputeErrorStatistics({3.0, 1.0, 4.0, 2.0});
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(30.0 / 4.0));
}

std::vector<double> EveryFiftyMs(double from, double to) {
  std::vector<double> stamps;
  for (int k = 0; 0.03 + 0.05 * k <= to; ++k) {
    const double t = 0.03 + 0.05 * k;  // 0.03, 0.08, ..., 9.98
    if (t >= from) stamps.push_back(t);
  }
  return stamps;
}

TEST(TrajectoryMetrics, FrameStepsSeeJitterThatAteHides) {
  // Truth moves 2 mm per frame along x; the estimate adds +-5 mm along y on alternate frames
  // and has one 0.5 s gap, whose step is skipped.
  PoseAssociation pairs;
  double stamp = 0.0;
  for (int k = 0; k < 10; ++k) {
    stamp += k == 5 ? 0.5 : 1.0 / 30.0;
    const Eigen::Vector3d truth(0.002 * k, 0.0, 0.0);
    const Eigen::Vector3d jitter(0.0, k % 2 == 0 ? 0.005 : -0.005, 0.0);
    pairs.groundtruth.push_back(MakePose(stamp, Eigen::Matrix3d::Identity(), truth));
    pairs.estimated.push_back(MakePose(stamp, Eigen::Matrix3d::Identity(), truth + jitter));
  }
  const FrameSteps steps = ComputeFrameSteps(pairs, 0.1);
  EXPECT_EQ(steps.num_steps, 8u);
  EXPECT_NEAR(steps.truth_step_m.median, 0.002, 1e-12);
  EXPECT_NEAR(steps.truth_step_m.max, 0.002, 1e-12);
  EXPECT_NEAR(steps.step_m.median, std::hypot(0.002, 0.010), 1e-12);
}

TEST(TrajectoryMetrics, GapsReduceCoverageByTheirLength) {
  EXPECT_NEAR(ComputeCoverage(EveryFiftyMs(0.0, 10.0), 0.0, 10.0, 0.1).fraction, 1.0, 1e-12);
  // Gap 2.98 -> 3.53 (0.55 s) is uncovered.
  std::vector<double> stamps = EveryFiftyMs(0.0, 3.0);
  for (double t : EveryFiftyMs(3.5, 10.0)) stamps.push_back(t);
  EXPECT_NEAR(ComputeCoverage(stamps, 0.0, 10.0, 0.1).covered_s, 9.45, 1e-9);
  // A late start (first estimate at 0.53 s) and an early end (last at 9.48 s) are uncovered too.
  std::vector<double> trimmed;
  for (double t : stamps) {
    if (t > 0.5 && t < 9.5) trimmed.push_back(t);
  }
  const Coverage c = ComputeCoverage(trimmed, 0.0, 10.0, 0.1);
  EXPECT_NEAR(c.covered_s, 9.45 - 0.53 - 0.52, 1e-9);
  EXPECT_NEAR(c.fraction, (9.45 - 0.53 - 0.52) / 10.0, 1e-9);
  EXPECT_DOUBLE_EQ(ComputeCoverage({}, 0.0, 10.0, 0.1).fraction, 0.0);
  EXPECT_THROW(ComputeCoverage({}, 1.0, 1.0, 0.1), std::invalid_argument);
}

TEST(TrajectoryMetrics, CoverageSpanIsFramesClippedToGroundTruth) {
  Trajectory groundtruth, estimated;
  for (int k = 0; k <= 1000; ++k) {
    groundtruth.push_back(
        MakePose(0.01 * k, Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.1 * k, 0, 0)));
  }
  for (double t : EveryFiftyMs(2.5, 10.0)) {
    estimated.push_back(MakePose(t, Eigen::Matrix3d::Identity(), Eigen::Vector3d(10 * t, 0, 0)));
  }
  // Frames span [-1, 12] clipped to [0, 10]: uncovered 0 -> 2.53.
  TrajectoryMetrics m = EvaluateTrajectory(estimated, groundtruth, {-1.0, 5.0, 12.0}, {});
  EXPECT_NEAR(m.coverage.fraction, (10.0 - 2.53) / 10.0, 1e-9);
  // Frames span [2, 8]: uncovered 2 -> 2.53.
  m = EvaluateTrajectory(estimated, groundtruth, {2.0, 8.0}, {});
  EXPECT_NEAR(m.coverage.fraction, (6.0 - 0.53) / 6.0, 1e-9);
  EXPECT_THROW(EvaluateTrajectory(estimated, groundtruth, {11.0, 12.0}, {}), std::runtime_error);
}

}  // namespace
}  // namespace dslam
