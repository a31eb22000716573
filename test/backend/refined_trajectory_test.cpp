// RefinedTrajectory: frames follow their keyframes' refined poses, erased keyframes keep their
// last pose until a loop correction moves them with the nearest keyframe it moved, and the compact record and block snapshots change the poses by less than the 1e-6 m
// the trajectory files print.
#include <gtest/gtest.h>

#include <iterator>
#include <map>

#include "dslam/backend/refined_trajectory.h"

namespace dslam {
namespace {

KeyFrame KeyFrameAt(int frame_index, double x) {
  KeyFrame keyframe;
  keyframe.frame_index = frame_index;
  keyframe.T_world_camera.translation() = Eigen::Vector3d(x, 0.0, 0.0);
  keyframe.measurements.T_camera_world = keyframe.T_world_camera.inverse();
  return keyframe;
}

Eigen::Isometry3d PoseNear(double x, double angle) {
  return Eigen::Translation3d(x, 0.3, -0.2) *
         Eigen::AngleAxisd(angle, Eigen::Vector3d(1.0, 2.0, 0.5).normalized());
}

TEST(RefinedTrajectory, FramesFollowTheirKeyFramesAndErasedOnesKeepTheirLastPose) {
  Map map;
  RefinedTrajectory refined;
  Trajectory causal;
  const int frames = static_cast<int>(2 * RefinedTrajectory::kBlock + 100);  // full blocks too
  for (int i = 0; i < frames; ++i) {
    if (i % 50 == 0) map.AddKeyFrame(KeyFrameAt(i, 0.01 * i), KeyFrameMapLimits::Newest(3));
    causal.push_back({0.1 * i, PoseNear(0.01 * i + 0.003 * (i % 50), 0.001 * i)});
    refined.AddFrame(causal.back().stamp_s, causal.back().T_world_camera, map);
  }
  ASSERT_EQ(refined.size(), static_cast<size_t>(frames));
  EXPECT_EQ(sizeof(RefinedTrajectory::Frame), 40u);
  Trajectory poses = refined.Poses();
  ASSERT_EQ(poses.size(), causal.size());
  for (size_t i = 0; i < poses.size(); ++i) {  // nothing refined yet: the causal poses
    EXPECT_DOUBLE_EQ(poses[i].stamp_s, causal[i].stamp_s);
    EXPECT_LT(
        (poses[i].T_world_camera.translation() - causal[i].T_world_camera.translation()).norm(),
        1e-6);
    EXPECT_TRUE(poses[i].T_world_camera.linear().isApprox(causal[i].T_world_camera.linear(), 1e-6));
  }
  // The back end moves the newest keyframe by 5 cm: its frames follow, older ones (their
  // keyframes erased from the map) stay.
  KeyFrame& newest = map.FindKeyFrame(map.window().back().id)[0];
  newest.T_world_camera.translation().y() += 0.05;
  refined.UpdateKeyFrames(map);
  const RefinedTrajectory::Snapshot snapshot = refined.Take();
  poses = snapshot.Poses();
  const int newest_first_frame = newest.frame_index;
  for (int i = 0; i < frames; i += 37) {
    const double dy =
        poses[i].T_world_camera.translation().y() - causal[i].T_world_camera.translation().y();
    EXPECT_NEAR(dy, i >= newest_first_frame ? 0.05 : 0.0, 1e-6) << i;
  }
  EXPECT_LE(snapshot.live.size(), 2 * map.num_keyframes() + 64);
}

// Full blocks of frames leave memory for a temporary file; a snapshot reads them even after the
// trajectory that wrote them is gone, and keeps its own frames while more are written.
TEST(RefinedTrajectory, FullBlocksGoToATemporaryFileThatSnapshotsKeep) {
  Map map;
  map.AddKeyFrame(KeyFrameAt(0, 0.0), KeyFrameMapLimits::Newest(3));
  RefinedTrajectory::Snapshot early, late;
  const size_t frames = 3 * RefinedTrajectory::kBlock + 7;
  {
    RefinedTrajectory refined;
    for (size_t i = 0; i < frames; ++i) {
      refined.AddFrame(0.1 * i, PoseNear(0.001 * i, 0.0), map);
      if (i + 1 == RefinedTrajectory::kBlock + 3) early = refined.Take();
    }
    ASSERT_TRUE(refined.FramesFiled());
    late = refined.Take();
    EXPECT_EQ(late.filed_blocks, 3u);
    EXPECT_EQ(late.frames.size(), 1u);  // only the open block in memory
  }
  const Trajectory early_poses = early.Poses(), late_poses = late.Poses();
  ASSERT_EQ(early_poses.size(), RefinedTrajectory::kBlock + 3);
  ASSERT_EQ(late_poses.size(), frames);
  for (size_t i = 0; i < frames; i += 101) {
    EXPECT_DOUBLE_EQ(late_poses[i].stamp_s, 0.1 * i);
    EXPECT_NEAR(late_poses[i].T_world_camera.translation().x(), 0.001 * i, 1e-6) << i;
    if (i < early_poses.size()) {
      EXPECT_DOUBLE_EQ(early_poses[i].stamp_s, 0.1 * i);
    }
  }
}

// A loop correction moves the keyframes in the map by 1, 2 and 3 m: the frames anchored on
// keyframes erased before it move with the nearest keyframe the correction moved (here the oldest
// in the map, none being older), the others with their own; a snapshot taken before keeps the old
// poses.
TEST(RefinedTrajectory, ALoopCorrectionMovesTheFramesOfErasedKeyFramesToo) {
  Map map;
  RefinedTrajectory refined;
  Trajectory causal;
  const int frames = static_cast<int>(RefinedTrajectory::kBlock + 400);  // a full block too
  for (int i = 0; i < frames; ++i) {
    if (i % 50 == 0) map.AddKeyFrame(KeyFrameAt(i, 0.01 * i), KeyFrameMapLimits::Newest(3));
    causal.push_back({0.1 * i, PoseNear(0.01 * i + 0.003 * (i % 50), 0.001 * i)});
    refined.AddFrame(causal.back().stamp_s, causal.back().T_world_camera, map);
  }
  refined.UpdateKeyFrames(map);  // the erased keyframes retire into their blocks
  const RefinedTrajectory::Snapshot before = refined.Take();
  ASSERT_EQ(map.window().size(), 3u);
  std::map<int, Eigen::Isometry3d> corrected;
  std::map<int, double> dy_of_keyframe;  // [m]
  double dy = 1.0;
  for (const KeyFrame& keyframe : map.window()) {
    Eigen::Isometry3d T = keyframe.T_world_camera;
    T.translation().y() += dy;
    corrected[keyframe.id] = T;
    dy_of_keyframe[keyframe.frame_index] = dy;
    dy += 1.0;
  }
  map.CorrectKeyFrames(corrected, {});
  refined.FollowCorrection(map);
  const Trajectory poses = refined.Poses();
  ASSERT_EQ(poses.size(), causal.size());
  for (int i = 0; i < frames; i += 13) {
    auto own = dy_of_keyframe.upper_bound(i);  // the frame's keyframe: the newest at or before i
    const double expected = own == dy_of_keyframe.begin() ? 1.0 : std::prev(own)->second;
    EXPECT_NEAR(poses[i].T_world_camera.translation().y() -
                    causal[i].T_world_camera.translation().y(),
                expected, 1e-6)
        << i;
    EXPECT_TRUE(poses[i].T_world_camera.linear().isApprox(causal[i].T_world_camera.linear(), 1e-6));
  }
  const Trajectory old_poses = before.Poses();
  EXPECT_NEAR(old_poses[0].T_world_camera.translation().y(),
              causal[0].T_world_camera.translation().y(), 1e-6);
}

}  // namespace
}  // namespace dslam
