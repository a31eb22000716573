// The odometry's resets (ResetMode), time going backwards, long gaps between frames and the
// per-frame lists a caller asks for, on a short static_room sequence rendered in-process.
#include <gtest/gtest.h>

#include "dslam/tracking/odometry.h"
#include "support/rendered_sequence.h"

namespace dslam {
namespace {

constexpr int kFrames = 40;

const test::RenderedSequence& Rendered() {
  static const test::RenderedSequence rendered = test::RenderSequence("static_room", kFrames);
  return rendered;
}

/// Ground-truth pose of frame `i` in the world of frame `origin` (the odometry's world).
Eigen::Isometry3d Truth(int i, int origin) {
  const Trajectory& gt = Rendered().groundtruth;
  return gt[origin].T_world_camera.inverse() * gt[i].T_world_camera;
}

double PositionError(const FrameResult& result, int i, int origin) {
  return (result.T_world_camera.translation() - Truth(i, origin).translation()).norm();
}

TEST(OdometryReset, KeepPoseContinuesTheWorldFrame) {
  Odometry odometry{Config()};
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(odometry.ProcessFrame(Rendered().frames[i]).has_pose);
  odometry.Reset(ResetMode::kKeepPose);
  const FrameResult first = odometry.ProcessFrame(Rendered().frames[20]);
  EXPECT_EQ(first.state, TrackingState::kInitialised);
  EXPECT_FALSE(first.has_pose);  // the assumed pose of a re-initialisation is never reported
  EXPECT_FALSE(first.reset);     // the caller reset; the frame itself did not
  // Frame 20 was assumed to be at frame 19's pose: the world after the reset is off by the
  // camera's motion between the two frames (measured 10-12 mm in all, with a step of ~9 mm).
  const double step = (Truth(20, 0).translation() - Truth(19, 0).translation()).norm();
  for (int i = 21; i < kFrames; ++i) {
    const FrameResult result = odometry.ProcessFrame(Rendered().frames[i]);
    ASSERT_TRUE(result.has_pose) << i;
    EXPECT_LT(PositionError(result, i, 0), step + 0.005) << i;
  }
  // Not the origin: the last frames are far from it.
  EXPECT_GT(Truth(kFrames - 1, 0).translation().norm(), 5 * (step + 0.005));
}

TEST(OdometryReset, NewWorldStartsAtTheOrigin) {
  Odometry odometry{Config()};
  for (int i = 0; i < 20; ++i) odometry.ProcessFrame(Rendered().frames[i]);
  odometry.Reset(ResetMode::kNewWorld);
  const FrameResult first = odometry.ProcessFrame(Rendered().frames[20]);
  EXPECT_TRUE(first.has_pose);  // the first frame of a world defines it
  EXPECT_TRUE(first.T_world_camera.isApprox(Eigen::Isometry3d::Identity()));
  const FrameResult later = odometry.ProcessFrame(Rendered().frames[30]);
  ASSERT_TRUE(later.has_pose);
  EXPECT_LT(PositionError(later, 30, 20), 0.01);
}

TEST(OdometryReset, TimeGoingBackwardsStartsANewWorld) {
  Odometry odometry{Config()};
  for (int i = 0; i < 30; ++i) odometry.ProcessFrame(Rendered().frames[i]);
  const FrameResult back = odometry.ProcessFrame(Rendered().frames[10]);
  EXPECT_TRUE(back.reset);
  EXPECT_EQ(back.message, "time went backwards: reset");
  EXPECT_EQ(back.frame_index, 0);
  EXPECT_TRUE(back.has_pose);
  EXPECT_TRUE(back.T_world_camera.isApprox(Eigen::Isometry3d::Identity()));
  for (int i = 11; i < 20; ++i) {
    const FrameResult result = odometry.ProcessFrame(Rendered().frames[i]);
    EXPECT_FALSE(result.reset);
    ASSERT_TRUE(result.has_pose) << i;
    EXPECT_LT(PositionError(result, i, 10), 0.01) << i;
  }
}

TEST(OdometryReset, LongGapPredictsTheLastPose) {
  Odometry odometry{Config()};
  for (int i = 0; i < 20; ++i) odometry.ProcessFrame(Rendered().frames[i]);
  RgbdFrame late = Rendered().frames[21];
  late.stamp_s += 30.0;  // a paused driver: the last velocity must not be applied for 30 s
  const FrameResult result = odometry.ProcessFrame(late);
  ASSERT_TRUE(result.has_pose);
  EXPECT_LT(PositionError(result, 21, 0), 0.01);
}

TEST(OdometryReset, ListsOnlyWhenAskedAndTheSamePoses) {
  Odometry full{Config()}, lean{Config()};
  FrameRequest none;
  none.points = none.edges = false;
  size_t points = 0, edges = 0;
  for (int i = 0; i < 15; ++i) {
    const FrameResult a = full.ProcessFrame(Rendered().frames[i]);
    const FrameResult b = lean.ProcessFrame(Rendered().frames[i], none);
    points += a.points.size();
    edges += a.edges.size();
    EXPECT_TRUE(b.points.empty() && b.edges.empty());
    EXPECT_EQ(a.counts.static_points, b.counts.static_points);
    EXPECT_TRUE(a.T_world_camera.isApprox(b.T_world_camera, 1e-12)) << i;
  }
  EXPECT_GT(points, 0u);
  EXPECT_GT(edges, 0u);
}

}  // namespace
}  // namespace dslam
