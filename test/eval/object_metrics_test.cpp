// Tests of the moving-object measurement with hand-made truth and estimates whose scores are
// known, and of the object file readers.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "dslam/eval/object_metrics.h"
#include "dslam/eval/trajectory_metrics.h"

namespace dslam {
namespace {

TruthObject Truth(double t, int id, const Eigen::Vector3d& p, const Eigen::Vector3d& v,
                  double share) {
  TruthObject o;
  o.stamp_s = t;
  o.id = id;
  o.position_m = p;
  o.velocity_mps = v;
  o.pixel_share = share;
  return o;
}

/// An estimate given in the world frame, stored in the estimate's frame (T_world_est^-1).
EstimatedObject Estimate(const Eigen::Isometry3d& T_world_est, double t, int id,
                         const Eigen::Vector3d& p_world, const Eigen::Vector3d& v_world) {
  EstimatedObject o;
  o.stamp_s = t;
  o.id = id;
  o.position_m = T_world_est.inverse() * p_world;
  o.velocity_mps = T_world_est.linear().transpose() * v_world;
  o.extent_m = Eigen::Vector3d(0.5, 0.5, 1.8);
  return o;
}

Trajectory StaticCamera(int frames) {
  Trajectory poses;
  for (int k = 0; k < frames; ++k) poses.push_back({0.1 * k, Eigen::Isometry3d::Identity()});
  return poses;
}

Eigen::Isometry3d SomeEstimateFrame() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  T.translation() = Eigen::Vector3d(0.3, -1.2, 1.5);
  return T;
}

TEST(ObjectMetrics, KnownScoresOfAHandMadeRun) {
  const Eigen::Isometry3d T = SomeEstimateFrame();
  const Eigen::Vector3d a(2.0, 0.0, 0.0), va(1.0, 0.0, 0.0), x(0.1, 0.0, 0.0);
  std::vector<TruthObject> truth;
  std::vector<EstimatedObject> est;
  for (int k = 0; k < 4; ++k) {
    const double t = 0.1 * k;
    truth.push_back(Truth(t, 1, a, va, 0.10));                          // evaluated
    truth.push_back(Truth(t, 2, Eigen::Vector3d(5, 0, 0), va, 0.10));   // beyond 4 m
    truth.push_back(Truth(t, 3, Eigen::Vector3d(0, 1, 0), va, 0.01));   // below 2 %
    est.push_back(Estimate(T, t, 20, Eigen::Vector3d(5, 0.2, 0), va));  // on id 2: ignored
  }
  // Object 1: matched by estimate 10 in frames 0 and 1 (10 cm and 20 cm off, velocity 0.2 and
  // 0.4 m/s off), missed in frame 2 (the estimate is 0.6 m away: a false object), matched by
  // estimate 11 in frame 3 (an id switch; 0.3 m and 0.6 m/s off).
  est.push_back(Estimate(T, 0.0, 10, a + x, va + Eigen::Vector3d(0, 0.2, 0)));
  est.push_back(Estimate(T, 0.1, 10, a + 2 * x, va + Eigen::Vector3d(0, 0, 0.4)));
  est.push_back(Estimate(T, 0.2, 10, a + 6 * x, va));
  est.push_back(Estimate(T, 0.3, 11, a - 3 * x, va - Eigen::Vector3d(0.6, 0, 0)));
  est.push_back(Estimate(T, 0.1, 30, Eigen::Vector3d(0, -3, 0), va));  // nothing there: false
  est.push_back(Estimate(T, 7.0, 40, a, va));  // no frame at 7 s: not scored
  const ObjectMetrics m = EvaluateObjects(truth, est, StaticCamera(4), T, ObjectMetricsOptions());
  EXPECT_EQ(m.frames, 4);
  EXPECT_EQ(m.truth_object_frames, 4);
  EXPECT_EQ(m.found, 3);
  EXPECT_DOUBLE_EQ(m.found_share, 0.75);
  EXPECT_EQ(m.estimated_object_frames, 4 + 4 + 1);
  EXPECT_EQ(m.ignored_estimates, 4);
  EXPECT_EQ(m.false_objects, 2);
  EXPECT_DOUBLE_EQ(m.false_share, 2.0 / 5.0);
  EXPECT_EQ(m.unassociated_estimates, 1);
  EXPECT_EQ(m.id_switches, 1);
  EXPECT_NEAR(m.centroid_error_median_m, 0.2, 1e-9);
  EXPECT_NEAR(m.velocity_error_median_mps, 0.4, 1e-9);
  EXPECT_NEAR(m.mota, 1.0 - (1 + 2 + 1) / 4.0, 1e-12);
}

TEST(ObjectMetrics, RangeIsMeasuredFromTheCameraOfEachFrame) {
  Trajectory poses = StaticCamera(2);
  poses[1].T_world_camera.translation() = Eigen::Vector3d(3.0, 0.0, 0.0);  // 2 m from (5, 0, 0)
  const Eigen::Vector3d p(5.0, 0.0, 0.0), v = Eigen::Vector3d::Zero();
  const std::vector<TruthObject> truth = {Truth(0.0, 1, p, v, 0.5), Truth(0.1, 1, p, v, 0.5)};
  const ObjectMetrics m =
      EvaluateObjects(truth, {}, poses, Eigen::Isometry3d::Identity(), ObjectMetricsOptions());
  EXPECT_EQ(m.truth_object_frames, 1);
  EXPECT_EQ(m.found, 0);
  EXPECT_DOUBLE_EQ(m.found_share, 0.0);
  EXPECT_DOUBLE_EQ(m.false_share, 0.0);  // no estimates
  EXPECT_TRUE(std::isnan(m.centroid_error_median_m));
}

TEST(ObjectMetrics, OneToOneMatchingWithinAFrame) {
  // Two people 0.4 m apart and two estimates between them: the assignment pairs each truth with
  // one estimate (total 0.3 m, not 0.5 m), never both with the same one.
  const Eigen::Vector3d v = Eigen::Vector3d::Zero();
  FrameObjects frame;
  frame.truth = {Truth(0, 1, Eigen::Vector3d(2.0, 0, 0), v, 0.1),
                 Truth(0, 2, Eigen::Vector3d(2.4, 0, 0), v, 0.1)};
  frame.estimated = {Estimate(Eigen::Isometry3d::Identity(), 0, 7, Eigen::Vector3d(2.25, 0, 0), v),
                     Estimate(Eigen::Isometry3d::Identity(), 0, 8, Eigen::Vector3d(2.15, 0, 0), v)};
  std::map<int, int> last;
  ObjectMetrics m;
  ScoreFrame(frame, ObjectMetricsOptions(), &last, &m);
  EXPECT_EQ(m.found, 2);
  EXPECT_EQ(m.false_objects, 0);
  EXPECT_EQ(last.at(1), 8);
  EXPECT_EQ(last.at(2), 7);
  ASSERT_EQ(m.centroid_errors_m.size(), 2u);
  EXPECT_NEAR(m.centroid_errors_m[0] + m.centroid_errors_m[1], 0.15 + 0.15, 1e-12);
}

TEST(ObjectFiles, ParsesLinesAndRejectsBadOnes) {
  std::istringstream truth("# header\n\n1000.033333 2 0.5 1 0.9 1 0 0 0.031\n");
  const std::vector<TruthObject> t = ParseTruthObjects(truth, "objects.txt");
  ASSERT_EQ(t.size(), 1u);
  EXPECT_DOUBLE_EQ(t[0].stamp_s, 1000.033333);
  EXPECT_EQ(t[0].id, 2);
  EXPECT_EQ(t[0].position_m, Eigen::Vector3d(0.5, 1, 0.9));
  EXPECT_EQ(t[0].velocity_mps, Eigen::Vector3d(1, 0, 0));
  EXPECT_DOUBLE_EQ(t[0].pixel_share, 0.031);
  std::istringstream est("# t id x y z vx vy vz ex ey ez\n5 3 1 2 3 4 5 6 0.4 0.5 1.7\n");
  const std::vector<EstimatedObject> e = ParseEstimatedObjects(est, "est.txt");
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].id, 3);
  EXPECT_EQ(e[0].extent_m, Eigen::Vector3d(0.4, 0.5, 1.7));
  std::istringstream short_line("5 3 1 2 3 4 5 6 0.4 0.5\n");
  EXPECT_THROW(ParseEstimatedObjects(short_line, "est.txt"), std::runtime_error);
  std::istringstream bad_id("5 3.5 1 2 3 4 5 6 0.1\n");
  EXPECT_THROW(ParseTruthObjects(bad_id, "objects.txt"), std::runtime_error);
  std::istringstream not_finite("5 3 nan 2 3 4 5 6 0.1\n");
  EXPECT_THROW(ParseTruthObjects(not_finite, "objects.txt"), std::runtime_error);
  EXPECT_THROW(ReadTruthObjects("/nonexistent/objects.txt"), std::runtime_error);
}

TEST(EstimateFrame, FirstFramePoseOrTheEstimatesFirstPose) {
  const Eigen::Isometry3d T = SomeEstimateFrame();
  Trajectory groundtruth = StaticCamera(3);
  groundtruth[1].T_world_camera = T;
  groundtruth[2].T_world_camera.translation() = Eigen::Vector3d(0.0, 0.0, 1.0);
  EXPECT_TRUE(EstimateFrameInWorld(groundtruth, 0.1001, {}, 0.005).isApprox(T));
  EXPECT_THROW(EstimateFrameInWorld(groundtruth, 0.15, {}, 0.005), std::runtime_error);
  // Tracking began at frame 1 with the pose P in the estimate's frame: the frame is T P^-1.
  Eigen::Isometry3d P = Eigen::Isometry3d::Identity();
  P.translation() = Eigen::Vector3d(0.5, 0.0, 0.0);
  const Trajectory estimated = {{0.2, P * P}, {0.1, P}};  // unsorted on purpose
  EXPECT_TRUE(EstimateFrameInWorld(groundtruth, 0.0, estimated, 0.005).isApprox(T * P.inverse()));
}

}  // namespace
}  // namespace dslam
