// The check of accepted loops against ground truth (dslam/eval/loop_check.h): a loop whose
// relative pose is the true one within 0.10 m and 3 deg is true, beyond either bound false; ground
// truth is interpolated between its poses; stamps it does not cover are not checked.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dslam/eval/loop_check.h"

namespace dslam {
namespace {

/// A camera walking a circle of radius 2 m at 100 Hz for 20 s, turning with it.
Trajectory CircleTruth() {
  Trajectory truth;
  for (int i = 0; i <= 2000; ++i) {
    const double t = 0.01 * i, angle = 2.0 * M_PI * t / 20.0;
    StampedPose pose;
    pose.stamp_s = 100.0 + t;
    pose.T_world_camera.linear() =
        Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    pose.T_world_camera.translation() =
        Eigen::Vector3d(2.0 * std::cos(angle), 2.0 * std::sin(angle), 1.3);
    truth.push_back(pose);
  }
  return truth;
}

LoopRecord TrueLoop(const Trajectory& truth, double query_s, double match_s) {
  Eigen::Isometry3d T_world_query, T_world_match;
  EXPECT_TRUE(InterpolatePose(truth, query_s, 0.1, &T_world_query));
  EXPECT_TRUE(InterpolatePose(truth, match_s, 0.1, &T_world_match));
  LoopRecord loop;
  loop.stamp_query_s = query_s;
  loop.stamp_match_s = match_s;
  loop.T_match_query = T_world_match.inverse() * T_world_query;
  return loop;
}

TEST(LoopCheck, InterpolatesBetweenGroundTruthPoses) {
  const Trajectory truth = CircleTruth();
  Eigen::Isometry3d T;
  ASSERT_TRUE(InterpolatePose(truth, 105.005, 0.1, &T));
  const double angle = 2.0 * M_PI * 5.005 / 20.0;
  // Linear between two points of the circle 1.2 cm apart: within 1e-5 m of the arc.
  EXPECT_NEAR(T.translation().x(), 2.0 * std::cos(angle), 1e-5);
  EXPECT_NEAR(T.translation().y(), 2.0 * std::sin(angle), 1e-5);
  EXPECT_NEAR(Eigen::AngleAxisd(T.rotation()).angle(), angle, 1e-9);
  EXPECT_TRUE(InterpolatePose(truth, 100.0, 0.1, &T));       // first pose, exactly
  EXPECT_FALSE(InterpolatePose(truth, 99.99, 0.1, &T));      // before it
  EXPECT_FALSE(InterpolatePose(truth, 120.02, 0.1, &T));     // after the last
  EXPECT_FALSE(InterpolatePose(truth, 105.005, 0.005, &T));  // poses 10 ms apart: a gap
}

TEST(LoopCheck, TrueLoopsWithinTheBoundsAndFalseOnesBeyond) {
  const Trajectory truth = CircleTruth();
  std::mt19937 rng(7);
  std::normal_distribution<double> noise_m(0.0, 0.01), noise_rad(0.0, 0.002);
  std::vector<LoopRecord> loops;
  for (int k = 0; k < 20; ++k) {  // true loops with centimetre noise
    LoopRecord loop = TrueLoop(truth, 119.0 - 0.1 * k, 100.5 + 0.1 * k);
    loop.T_match_query.translation() += Eigen::Vector3d(noise_m(rng), noise_m(rng), noise_m(rng));
    loop.T_match_query.linear() =
        loop.T_match_query.rotation() *
        Eigen::AngleAxisd(noise_rad(rng), Eigen::Vector3d::UnitX()).toRotationMatrix();
    loops.push_back(loop);
  }
  LoopRecord shifted = TrueLoop(truth, 118.0, 101.0);  // 0.12 m off: false
  shifted.T_match_query.translation().y() += 0.12;
  LoopRecord turned = TrueLoop(truth, 117.0, 102.0);  // 3.5 deg off: false
  turned.T_match_query.linear() =
      turned.T_match_query.rotation() *
      Eigen::AngleAxisd(3.5 * M_PI / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
  LoopRecord outside = TrueLoop(truth, 118.5, 101.5);  // stamp past the ground truth
  outside.stamp_query_s = 130.0;
  loops.insert(loops.end(), {shifted, turned, outside});

  const LoopCheck check = CheckLoops(loops, truth);
  ASSERT_EQ(check.verdicts.size(), 23u);
  EXPECT_EQ(check.checked, 22);
  EXPECT_EQ(check.false_loops, 2);
  for (int k = 0; k < 20; ++k) EXPECT_FALSE(check.verdicts[k].false_loop) << k;
  EXPECT_TRUE(check.verdicts[20].false_loop);
  EXPECT_NEAR(check.verdicts[20].translation_error_m, 0.12, 1e-9);
  EXPECT_TRUE(check.verdicts[21].false_loop);
  EXPECT_NEAR(check.verdicts[21].rotation_error_deg, 3.5, 1e-6);
  EXPECT_FALSE(check.verdicts[22].checked);
  EXPECT_FALSE(check.verdicts[22].false_loop);
  EXPECT_NEAR(check.max_translation_error_m, 0.12, 1e-9);
  EXPECT_NEAR(check.max_rotation_error_deg, 3.5, 1e-6);
  // The cameras of the first loop are 18.5 s = 333 deg of the circle apart: 2 * 2 m * sin(13.5
  // deg).
  EXPECT_NEAR(check.verdicts[0].true_distance_m, 4.0 * std::sin(13.5 * M_PI / 180.0), 1e-4);
}

TEST(LoopCheck, TheBoundsAreOptions) {
  const Trajectory truth = CircleTruth();
  LoopRecord loop = TrueLoop(truth, 118.0, 101.0);
  loop.T_match_query.translation().x() += 0.05;
  LoopCheckOptions strict;
  strict.max_translation_m = 0.04;
  EXPECT_EQ(CheckLoops({loop}, truth).false_loops, 0);
  EXPECT_EQ(CheckLoops({loop}, truth, strict).false_loops, 1);
}

}  // namespace
}  // namespace dslam
