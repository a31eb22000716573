// The back end refines keyframe poses between frames (Slam): Odometry::AdoptNewestKeyFramePose
// must carry the last tracked pose along with the newest keyframe, whether or not that keyframe
// was made from the last tracked frame (in threaded mode it mostly is not); the next frame
// reports the corrected pose as the one it was tracked from (FrameResult::
// T_world_previous_camera, which the ROS layer's odom integrates without the correction).
#include <gtest/gtest.h>

#include "dslam/tracking/odometry.h"
#include "support/rendered_sequence.h"

namespace dslam {
namespace {

constexpr char kScene[] = "static_room";
constexpr int kFrames = 40;

// A rigid correction of the whole map, T_world_new_old, as local BA makes (1-2 cm, 0.6 deg).
Eigen::Isometry3d Correction() {
  return Eigen::Translation3d(0.01, -0.02, 0.005) *
         Eigen::AngleAxisd(0.01, Eigen::Vector3d(0.3, 1.0, 0.2).normalized());
}

void CorrectMap(const Eigen::Isometry3d& C, Map* map) {
  for (KeyFrame& keyframe : map->mutable_window()) {
    keyframe.T_world_camera = C * keyframe.T_world_camera;
    keyframe.measurements.T_camera_world = keyframe.T_world_camera.inverse();
  }
}

// Tracks frames until the last one tracked was made a keyframe (`keyframe_last`) or until one
// after the newest keyframe was tracked and was not (!keyframe_last).
void TrackUntil(Odometry* odometry, bool keyframe_last) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  bool after_keyframe = false;
  for (int i = 0; i < kFrames; ++i) {
    const FrameResult r = odometry->ProcessFrame(room.frames[i]);
    ASSERT_TRUE(r.has_pose || i == 0) << i;
    if (i < 3) continue;
    if (keyframe_last && r.keyframe) return;
    if (!keyframe_last && after_keyframe && !r.keyframe) return;
    after_keyframe = after_keyframe || r.keyframe;
  }
  FAIL() << "no such frame";
}

TEST(OdometryCorrection, LastPoseFollowsTheNewestKeyFrameMadeBeforeIt) {
  Odometry odometry{Config()};
  TrackUntil(&odometry, false);
  ASSERT_NE(odometry.map().window().back().frame_index, kFrames);
  const Eigen::Isometry3d T_world_last = odometry.T_world_last_camera();
  CorrectMap(Correction(), odometry.mutable_map());
  odometry.AdoptNewestKeyFramePose();
  EXPECT_TRUE(odometry.T_world_last_camera().isApprox(Correction() * T_world_last, 1e-12))
      << "before\n"
      << T_world_last.matrix() << "\nafter\n"
      << odometry.T_world_last_camera().matrix();
}

TEST(OdometryCorrection, LastPoseIsTheNewestKeyFramesWhenItWasMadeFromIt) {
  Odometry odometry{Config()};
  TrackUntil(&odometry, true);
  CorrectMap(Correction(), odometry.mutable_map());
  odometry.AdoptNewestKeyFramePose();
  EXPECT_TRUE(odometry.T_world_last_camera().matrix() ==
              odometry.map().window().back().T_world_camera.matrix());
}

TEST(OdometryCorrection, EachFrameReportsThePoseItWasTrackedFrom) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  Odometry odometry{Config()};
  const FrameResult first = odometry.ProcessFrame(room.frames[0]);
  ASSERT_TRUE(first.has_pose);
  EXPECT_FALSE(first.has_previous_pose);  // the first frame defines the world
  Eigen::Isometry3d previous = first.T_world_camera;
  for (int i = 1; i < 10; ++i) {
    const FrameResult r = odometry.ProcessFrame(room.frames[i]);
    ASSERT_TRUE(r.has_pose) << i;
    EXPECT_TRUE(r.has_previous_pose) << i;
    // Nothing corrected it: exactly the pose the previous frame reported.
    EXPECT_TRUE(r.T_world_previous_camera.matrix() == previous.matrix()) << i;
    previous = r.T_world_camera;
  }
  // A correction between frames: the next frame was tracked from the corrected pose.
  CorrectMap(Correction(), odometry.mutable_map());
  odometry.AdoptNewestKeyFramePose();
  const Eigen::Isometry3d corrected = odometry.T_world_last_camera();
  ASSERT_FALSE(corrected.isApprox(previous, 1e-6));
  const FrameResult next = odometry.ProcessFrame(room.frames[10]);
  ASSERT_TRUE(next.has_pose);
  EXPECT_TRUE(next.has_previous_pose);
  EXPECT_TRUE(next.T_world_previous_camera.matrix() == corrected.matrix());
}

}  // namespace
}  // namespace dslam
