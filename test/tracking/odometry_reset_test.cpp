// The odometry's resets (ResetMode), time going backwards, long gaps between frames and the
// per-frame lists a caller asks for, on a short static_room sequence rendered in-process, and
// relocalisation after a jump on fast_rotation, and the wide search when the narrow one fails.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/synth/scenario.h"
#include "dslam/synth/sequence.h"
#include "dslam/tracking/odometry.h"
#include "support/rendered_sequence.h"

namespace dslam {
namespace {

// The sequence of the tests but fast_rotation's: test::SharedSequence(kScene, kFrames).
constexpr char kScene[] = "static_room";
constexpr int kFrames = 40;

/// Ground-truth pose of frame `i` in the world of frame `origin` (the odometry's world).
Eigen::Isometry3d Truth(int i, int origin) {
  const Trajectory& gt = test::SharedSequence(kScene, kFrames).groundtruth;
  return gt[origin].T_world_camera.inverse() * gt[i].T_world_camera;
}

double PositionError(const FrameResult& result, int i, int origin) {
  return (result.T_world_camera.translation() - Truth(i, origin).translation()).norm();
}

TEST(OdometryReset, KeepPoseContinuesTheWorldFrame) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  Odometry odometry{Config()};
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(odometry.ProcessFrame(room.frames[i]).has_pose);
  const Eigen::Isometry3d T_world_19 = odometry.T_world_last_camera();
  odometry.Reset(ResetMode::kKeepPose);
  const FrameResult first = odometry.ProcessFrame(room.frames[20]);
  EXPECT_EQ(first.state, TrackingState::kInitialised);
  EXPECT_FALSE(first.has_pose);  // the assumed pose of a re-initialisation is never reported
  EXPECT_FALSE(first.has_previous_pose);
  EXPECT_FALSE(first.reset);  // the caller reset; the frame itself did not
  // Frame 21 is tracked from the re-initialised frame, at frame 19's pose.
  const FrameResult second = odometry.ProcessFrame(room.frames[21]);
  ASSERT_TRUE(second.has_pose);
  EXPECT_TRUE(second.has_previous_pose);
  EXPECT_TRUE(second.T_world_previous_camera.matrix() == T_world_19.matrix());
  // Frame 20 was assumed to be at frame 19's pose: the world after the reset is off by the
  // camera's motion between the two frames (measured 10-12 mm in all, with a step of ~9 mm).
  const double step = (Truth(20, 0).translation() - Truth(19, 0).translation()).norm();
  EXPECT_LT(PositionError(second, 21, 0), step + 0.005);
  for (int i = 22; i < kFrames; ++i) {
    const FrameResult result = odometry.ProcessFrame(room.frames[i]);
    ASSERT_TRUE(result.has_pose) << i;
    EXPECT_LT(PositionError(result, i, 0), step + 0.005) << i;
  }
  // Not the origin: the last frames are far from it.
  EXPECT_GT(Truth(kFrames - 1, 0).translation().norm(), 5 * (step + 0.005));
}

TEST(OdometryReset, NewWorldStartsAtTheOrigin) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  Odometry odometry{Config()};
  for (int i = 0; i < 20; ++i) odometry.ProcessFrame(room.frames[i]);
  odometry.Reset(ResetMode::kNewWorld);
  const FrameResult first = odometry.ProcessFrame(room.frames[20]);
  EXPECT_TRUE(first.has_pose);  // the first frame of a world defines it
  EXPECT_TRUE(first.T_world_camera.isApprox(Eigen::Isometry3d::Identity()));
  const FrameResult later = odometry.ProcessFrame(room.frames[30]);
  ASSERT_TRUE(later.has_pose);
  EXPECT_LT(PositionError(later, 30, 20), 0.01);
}

TEST(OdometryReset, TimeGoingBackwardsStartsANewWorld) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  Odometry odometry{Config()};
  for (int i = 0; i < 30; ++i) odometry.ProcessFrame(room.frames[i]);
  const FrameResult back = odometry.ProcessFrame(room.frames[10]);
  EXPECT_TRUE(back.reset);
  EXPECT_EQ(back.message, "time went backwards: reset");
  EXPECT_EQ(back.frame_index, 0);
  EXPECT_TRUE(back.has_pose);
  EXPECT_FALSE(back.has_previous_pose);  // the old world's poses are not this one's
  EXPECT_TRUE(back.T_world_camera.isApprox(Eigen::Isometry3d::Identity()));
  for (int i = 11; i < 20; ++i) {
    const FrameResult result = odometry.ProcessFrame(room.frames[i]);
    EXPECT_FALSE(result.reset);
    ASSERT_TRUE(result.has_pose) << i;
    EXPECT_TRUE(result.has_previous_pose) << i;
    EXPECT_LT(PositionError(result, i, 10), 0.01) << i;
  }
}

TEST(OdometryReset, LongGapPredictsTheLastPose) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  Odometry odometry{Config()};
  for (int i = 0; i < 20; ++i) odometry.ProcessFrame(room.frames[i]);
  RgbdFrame late = room.frames[21];
  late.stamp_s += 30.0;  // a paused driver: the last velocity must not be applied for 30 s
  const FrameResult result = odometry.ProcessFrame(late);
  ASSERT_TRUE(result.has_pose);
  EXPECT_LT(PositionError(result, 21, 0), 0.01);
}

// fast_rotation (turning at up to 60 deg/s), seed 1: frames 0-19, and frame 31.
struct Turning {
  std::vector<synth::SyntheticFrame> first;
  synth::SyntheticFrame later;
};

const Turning& TurningFrames() {
  static const Turning turning = [] {
    const synth::SyntheticSequence sequence(synth::MakeScenario("fast_rotation", 1));
    Turning out;
    for (int i = 0; i < 20; ++i) out.first.push_back(sequence.RenderFrame(i));
    out.later = sequence.RenderFrame(31);
    return out;
  }();
  return turning;
}

// Feeds frames 0-19 of TurningFrames to `odometry` (all tracked).
void TrackFirstFrames(Odometry* odometry) {
  for (const synth::SyntheticFrame& frame : TurningFrames().first) {
    ASSERT_TRUE(odometry->ProcessFrame(frame.frame).has_pose);
  }
}

// The pose of `result` is TurningFrames().later's (in the world of frame 0): < 1 cm, < 0.5 deg.
void ExpectAtLaterFrame(const FrameResult& result) {
  const Turning& turning = TurningFrames();
  const Eigen::Isometry3d truth =
      turning.first[0].T_world_camera.inverse() * turning.later.T_world_camera;
  EXPECT_LT((result.T_world_camera.translation() - truth.translation()).norm(), 0.01);
  const Eigen::AngleAxisd error(result.T_world_camera.linear().transpose() * truth.linear());
  EXPECT_LT(error.angle(), 0.5 * M_PI / 180.0);
}

Config WithoutRelocalisation() {
  Config config;
  config.tracking.relocalisation = false;
  return config;
}

// A jump the motion model cannot predict: frames 20-30 never arrive, the stamps say 1/30 s
// passed. The projection search around the prediction fails (its wide radius as narrow as the
// narrow one here: the 30 px radius finds this jump at the upper pyramid levels);
// relocalisation by descriptors against the window's keyframes finds the pose.
TEST(OdometryReset, RelocalisesAfterAnUnpredictedJump) {
  Config with_relocalisation, without_relocalisation = WithoutRelocalisation();
  with_relocalisation.tracking.wide_search_radius_px =
      with_relocalisation.tracking.search_radius_px;
  without_relocalisation.tracking.wide_search_radius_px =
      without_relocalisation.tracking.search_radius_px;
  Odometry on{with_relocalisation}, off{without_relocalisation};
  TrackFirstFrames(&on);
  TrackFirstFrames(&off);
  RgbdFrame jumped = TurningFrames().later.frame;
  jumped.stamp_s = TurningFrames().first.back().frame.stamp_s + 1.0 / 30.0;
  const FrameResult without = off.ProcessFrame(jumped);
  EXPECT_EQ(without.state, TrackingState::kLost);  // the case relocalisation is for
  const FrameResult with = on.ProcessFrame(jumped);
  ASSERT_TRUE(with.has_pose) << with.message;
  EXPECT_EQ(with.state, TrackingState::kRecovered);
  EXPECT_NE(with.message.find("relocalised"), std::string::npos) << with.message;
  EXPECT_FALSE(with.has_previous_pose);  // a jump, not tracked motion (ROS: into map -> odom)
  ExpectAtLaterFrame(with);
}

// The frame after initialisation has no velocity to predict with: fast_rotation's frame 2 turned
// 5 deg from frame 0 (about 45 px; the radii grow with the pyramid level), beyond
// search_radius_px (10) and within wide_search_radius_px (30) at the upper levels. The narrow
// search finds enough matches not to search the rest wide (min_matches 3), but too few right
// ones for a pose with min_static_inliers (100 here; in a real frame, blur leaves many wrong
// matches: TUM fr1/rpy frame 1). Matching again with the wide radius gives the pose, without
// relocalisation.
TEST(OdometryReset, SearchesWideWhenTheNarrowSearchGivesNoPose) {
  Config config = WithoutRelocalisation();
  config.tracking.min_matches = 3;
  config.tracking.min_static_inliers = 100;
  Odometry odometry{config};
  ASSERT_TRUE(odometry.ProcessFrame(TurningFrames().first[0].frame).has_pose);
  const FrameResult r = odometry.ProcessFrame(TurningFrames().first[2].frame);
  ASSERT_TRUE(r.has_pose) << r.message;
  const Eigen::Isometry3d truth =
      TurningFrames().first[0].T_world_camera.inverse() * TurningFrames().first[2].T_world_camera;
  EXPECT_LT((r.T_world_camera.translation() - truth.translation()).norm(), 0.01);
  const Eigen::AngleAxisd error(r.T_world_camera.linear().transpose() * truth.linear());
  EXPECT_LT(error.angle(), 0.5 * M_PI / 180.0);
}

// A covered lens: frames 20-30 are black without depth, more than lost_frames_before_reset
// (10). Without relocalisation frame 31 re-initialises the map at frame 19's pose; with it, frame
// 31 is relocalised in the map kept since.
TEST(OdometryReset, RelocalisesInTheKeptMapAfterACoveredLens) {
  Odometry on{Config()}, off{WithoutRelocalisation()};
  TrackFirstFrames(&on);
  TrackFirstFrames(&off);
  const RgbdFrame& last = TurningFrames().first.back().frame;
  for (int k = 1; k <= 11; ++k) {
    RgbdFrame black = last;
    black.colour = cv::Mat::zeros(last.colour.size(), last.colour.type());
    black.depth_m = cv::Mat::zeros(last.depth_m.size(), CV_32FC1);
    black.stamp_s = last.stamp_s + k / 30.0;
    EXPECT_EQ(off.ProcessFrame(black).state, TrackingState::kLost);
    const FrameResult lost = on.ProcessFrame(black);
    EXPECT_EQ(lost.state, TrackingState::kLost);
    EXPECT_FALSE(lost.has_previous_pose);
  }
  const FrameResult without = off.ProcessFrame(TurningFrames().later.frame);
  EXPECT_EQ(without.state, TrackingState::kInitialised);
  EXPECT_FALSE(without.has_pose);
  const FrameResult with = on.ProcessFrame(TurningFrames().later.frame);
  ASSERT_TRUE(with.has_pose) << with.message;
  EXPECT_EQ(with.state, TrackingState::kRecovered);
  EXPECT_FALSE(with.has_previous_pose);  // after lost frames
  ExpectAtLaterFrame(with);
}

TEST(OdometryReset, ListsOnlyWhenAskedAndTheSamePoses) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  Odometry full{Config()}, lean{Config()};
  FrameRequest none;
  none.points = none.edges = false;
  size_t points = 0, edges = 0;
  for (int i = 0; i < 15; ++i) {
    const FrameResult a = full.ProcessFrame(room.frames[i]);
    const FrameResult b = lean.ProcessFrame(room.frames[i], none);
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
