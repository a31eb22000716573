// Bad input reaching the core (Slam: front end and back end, synchronous): frames without valid
// depth, black, saturated or textureless colour, and a moving object covering the whole view,
// fed after a good start on rendered sequences whose camera poses are known. Each must give no
// crash, no pose while it lasts (or a pose near the truth) and a continuous pose when good
// frames return.
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/backend/slam.h"
#include "dslam/synth/sequence.h"
#include "support/rendered_sequence.h"

namespace dslam {
namespace {

constexpr int kGoodStart = 30;  // good frames before the bad ones
constexpr int kGoodEnd = 30;    // good frames after them
constexpr int kShortGap = 5;    // bad frames: fewer than tracking.lost_frames_before_reset (10)
constexpr int kLongGap = 15;    // bad frames: more (without relocalisation: re-initialised)
constexpr int kRoomFrames = kGoodStart + kLongGap + kGoodEnd;  // of static_room, rendered once

/// Ground truth T_world_camera relative to the first frame's camera (the odometry's world).
Eigen::Isometry3d Truth(const Trajectory& groundtruth, size_t i) {
  return groundtruth[0].T_world_camera.inverse() * groundtruth[i].T_world_camera;
}

struct RunResult {
  std::vector<FrameResult> results;
  double max_error_good_m = 0.0;  ///< largest translation error of a reported pose, good frames
  double max_error_bad_m = 0.0;   ///< the same over the bad frames
  int bad_with_pose = 0;          ///< bad frames with a reported pose
  int first_pose_after = -1;      ///< frames after the last bad one until a pose is reported
};

/// The back end on, the depth model static_room's sensor's (every scene here is static_room's),
/// the rest default.
Config WithBackEnd() {
  Config config;
  synth::UseSensorDepthNoise(synth::MakeScenario("static_room", 1).sensor, &config.depth_noise);
  config.backend.enabled = true;
  return config;
}

/// Runs Slam with `config` over `frames`, where frames [bad_begin, bad_end) are the bad ones.
RunResult RunSlam(const std::vector<RgbdFrame>& frames, const Trajectory& groundtruth,
                  int bad_begin, int bad_end, const Config& config) {
  Slam slam(config);
  RunResult run;
  for (size_t i = 0; i < frames.size(); ++i) {
    FrameResult result = slam.ProcessFrame(frames[i]);
    const bool bad = static_cast<int>(i) >= bad_begin && static_cast<int>(i) < bad_end;
    if (result.has_pose) {
      const double error =
          (result.T_world_camera.translation() - Truth(groundtruth, i).translation()).norm();
      double& worst = bad ? run.max_error_bad_m : run.max_error_good_m;
      worst = std::max(worst, error);
      run.bad_with_pose += bad;
      if (static_cast<int>(i) >= bad_end && run.first_pose_after < 0) {
        run.first_pose_after = static_cast<int>(i) - bad_end;
      }
    }
    if (std::getenv("DSLAM_BAD_INPUT_VERBOSE")) {
      std::cout << i << (bad ? " bad " : " good ") << ToString(result.state) << " pose "
                << result.has_pose << " features " << result.counts.features << " with depth "
                << result.counts.features_with_depth << " inliers " << result.counts.pose_inliers
                << " '" << result.message << "' t "
                << result.T_world_camera.translation().transpose() << " truth "
                << Truth(groundtruth, i).translation().transpose() << "\n";
    }
    run.results.push_back(std::move(result));
  }
  return run;
}

/// Runs the static room with frames [kGoodStart, kGoodStart + gap) spoilt by `spoil`.
RunResult RunSpoilt(const std::function<void(RgbdFrame*)>& spoil, int gap,
                    const Config& config = WithBackEnd()) {
  const test::RenderedSequence& room = test::SharedSequence("static_room", kRoomFrames);
  std::vector<RgbdFrame> frames;
  const int total = kGoodStart + gap + kGoodEnd;
  for (int i = 0; i < total; ++i) {
    RgbdFrame frame = room.frames[i];
    frame.colour = frame.colour.clone();
    frame.depth_m = frame.depth_m.clone();
    if (i >= kGoodStart && i < kGoodStart + gap) spoil(&frame);
    frames.push_back(std::move(frame));
  }
  Trajectory truth(room.groundtruth.begin(), room.groundtruth.begin() + total);
  return RunSlam(frames, truth, kGoodStart, kGoodStart + gap, config);
}

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

void ZeroDepth(RgbdFrame* f) { f->depth_m.setTo(0.0f); }
void NanDepth(RgbdFrame* f) { f->depth_m.setTo(kNaN); }
void InfiniteDepth(RgbdFrame* f) { f->depth_m.setTo(kInf); }
void BlackColour(RgbdFrame* f) { f->colour.setTo(cv::Scalar::all(0)); }
void SaturatedColour(RgbdFrame* f) { f->colour.setTo(cv::Scalar::all(255)); }
void TexturelessColour(RgbdFrame* f) { f->colour.setTo(cv::Scalar(90, 120, 150)); }

// Without valid depth the frame is tracked against the map with pixel-only observations: a pose
// near the truth (measured 4.1 mm worst over 5 and 15 such frames, 3.8-3.9 mm on good frames).
void ExpectTrackedFromTheMap(const RunResult& run, int gap) {
  EXPECT_EQ(run.bad_with_pose, gap);
  EXPECT_LT(run.max_error_bad_m, 0.01);
  EXPECT_LT(run.max_error_good_m, 0.01);
}

TEST(BadInput, ZeroDepthIsTrackedFromTheMap) {
  ExpectTrackedFromTheMap(RunSpoilt(ZeroDepth, kLongGap), kLongGap);
}
TEST(BadInput, NanDepthIsTrackedFromTheMap) {
  ExpectTrackedFromTheMap(RunSpoilt(NanDepth, kShortGap), kShortGap);
}
TEST(BadInput, InfiniteDepthIsTrackedFromTheMap) {
  ExpectTrackedFromTheMap(RunSpoilt(InfiniteDepth, kShortGap), kShortGap);
}

TEST(BadInput, NoValidDepthAtTheStartIsLostUntilDepthReturns) {
  const test::RenderedSequence& room = test::SharedSequence("static_room", kRoomFrames);
  Slam slam(Config{});
  for (int i = 0; i < 3; ++i) {
    RgbdFrame frame = room.frames[i];
    frame.depth_m = cv::Mat(frame.depth_m.size(), CV_32FC1, cv::Scalar(kNaN));
    const FrameResult result = slam.ProcessFrame(frame);
    EXPECT_FALSE(result.has_pose);
    EXPECT_EQ(result.state, TrackingState::kLost);
    EXPECT_EQ(result.message, "too few features with depth to initialise");
  }
  const FrameResult result = slam.ProcessFrame(room.frames[3]);
  EXPECT_TRUE(result.has_pose);
  EXPECT_EQ(result.state, TrackingState::kInitialised);
}

// Black, saturated and textureless images have no ORB features: lost with the reason, and the
// next good frame is tracked against the map again (measured: at once, 3.8 mm worst error).
void ExpectLostThenRecovered(const RunResult& run) {
  EXPECT_EQ(run.bad_with_pose, 0);
  for (int i = kGoodStart; i < kGoodStart + kShortGap; ++i) {
    EXPECT_EQ(run.results[i].state, TrackingState::kLost);
    EXPECT_EQ(run.results[i].message,
              "too few features (0 ORB keypoints: black, saturated or textureless image?)");
  }
  EXPECT_EQ(run.first_pose_after, 0);
  EXPECT_LT(run.max_error_good_m, 0.01);
}

TEST(BadInput, BlackColourIsLostThenRecovered) {
  ExpectLostThenRecovered(RunSpoilt(BlackColour, kShortGap));
}
TEST(BadInput, SaturatedColourIsLostThenRecovered) {
  ExpectLostThenRecovered(RunSpoilt(SaturatedColour, kShortGap));
}
TEST(BadInput, TexturelessColourIsLostThenRecovered) {
  ExpectLostThenRecovered(RunSpoilt(TexturelessColour, kShortGap));
}

// More lost frames than tracking.lost_frames_before_reset: the map is kept until a frame can be
// neither tracked nor relocalised in it. The first good frame is tracked in it at once, with the
// camera's motion during the gap (measured 4.0 mm worst error over the good frames).
TEST(BadInput, LongBlackGapIsFoundAgainInTheKeptMap) {
  const RunResult run = RunSpoilt(BlackColour, kLongGap);
  EXPECT_EQ(run.bad_with_pose, 0);
  EXPECT_EQ(run.first_pose_after, 0);
  EXPECT_NE(run.results[kGoodStart + kLongGap].state, TrackingState::kInitialised);
  EXPECT_LT(run.max_error_good_m, 0.01);
}

// Without relocalisation the map is dropped and the first good frame re-initialises at the last
// good pose (no pose reported for it). The camera's motion during the gap is not recovered:
// measured 65.6 mm worst error afterwards for this 15-frame gap of the xyz motion.
TEST(BadInput, LongBlackGapWithoutRelocalisationReinitialisesAtTheLastGoodPose) {
  Config config = WithBackEnd();
  config.tracking.relocalisation = false;
  const RunResult run = RunSpoilt(BlackColour, kLongGap, config);
  EXPECT_EQ(run.bad_with_pose, 0);
  const FrameResult& first_good = run.results[kGoodStart + kLongGap];
  EXPECT_FALSE(first_good.has_pose);
  EXPECT_EQ(first_good.state, TrackingState::kInitialised);
  EXPECT_EQ(first_good.message, "re-initialised at the last good pose");
  EXPECT_EQ(run.first_pose_after, 1);
  EXPECT_GT(run.max_error_good_m, 0.03);
}

/// The static room seen by a camera that moves as `motion` (static: no jitter), with a textured
/// 4 m x 3 m board 1.2 m in front of the camera's base position when `board`, sliding right at
/// `speed_mps`: out of view for the first kGoodStart frames, then entering the view from the left.
synth::Scenario BoardScenario(synth::CameraMotionKind motion, bool board, double speed_mps) {
  synth::Scenario s = synth::MakeScenario("static_room", 1);
  s.camera.kind = motion;
  s.camera.jitter_translation_m = 0.0;
  s.camera.jitter_rotation_deg = 0.0;
  if (board) {
    synth::MovingBoxParams b;
    b.size_m = {4.0, 0.1, 3.0};
    const double per_frame = speed_mps / s.fps;
    // Centre x at which the right edge reaches the view (0.73 m half-width at 1.2 m), kGoodStart
    // frames early.
    const double start_x = -2.0 - 0.75 - kGoodStart * per_frame;
    b.start_m = {start_x, -0.6, 1.2};
    b.end_m = {start_x + 10.0, -0.6, 1.2};
    b.speed_mps = speed_mps;
    b.look_seed = 5;
    s.boxes = {b};
  }
  return s;
}

// A board sliding in at 4 cm per frame in front of a still camera: with up to ~90% of the view
// covered (frame 63) the pose stays within 1 cm of the truth (measured 9.9 mm worst, at frame 57).
// Known failure beyond: from frame 65 (96% covered) the remaining room points are below
// tracking.min_static_inliers, the RANSAC fallback takes the board's marked points and the pose
// follows the board (measured 1.40 m error at frame 99 with the board filling the view from frame
// 70; the same with the xyz camera motion).
TEST(BadInput, BoardCoveringMostOfTheViewDoesNotMoveThePose) {
  constexpr int kFrames = 64;
  const synth::SyntheticSequence sequence(
      BoardScenario(synth::CameraMotionKind::kStatic, true, 1.2));
  std::vector<RgbdFrame> frames;
  Trajectory truth;
  double covered = 0.0;
  for (int i = 0; i < kFrames; ++i) {
    synth::SyntheticFrame f = sequence.RenderFrame(i);
    if (i < kGoodStart) {
      EXPECT_LT(f.dynamic_fraction, 0.01);  // its edge enters at frame 29
    }
    covered = f.dynamic_fraction;
    truth.push_back({f.frame.stamp_s, f.T_world_camera});
    frames.push_back(std::move(f.frame));
  }
  EXPECT_GT(covered, 0.85);
  const RunResult run = RunSlam(frames, truth, kGoodStart, kFrames, WithBackEnd());
  EXPECT_EQ(run.bad_with_pose, kFrames - kGoodStart);
  EXPECT_LT(run.max_error_bad_m, 0.02);
}

}  // namespace
}  // namespace dslam
