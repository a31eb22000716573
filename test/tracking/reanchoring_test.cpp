// Re-anchoring's pieces (reanchoring.h): the weak-episode state, the older points it checks
// against, and Map::MoveMadeSince, which moves what was made since the episode began.
#include "dslam/tracking/reanchoring.h"

#include <gtest/gtest.h>

namespace dslam {
namespace {

TrackingConfig Thresholds() {
  TrackingConfig config;
  config.reanchor_weak_inliers = 60;
  config.reanchor_strong_inliers = 120;
  return config;
}

TEST(WeakEpisode, BeginsAtAWeakPoseAndIsCheckedAtAStrongOneLater) {
  const TrackingConfig config = Thresholds();
  WeakEpisode episode;
  EXPECT_FALSE(episode.Update(10, 300, config));  // strong, no episode
  EXPECT_EQ(episode.first_frame(), -1);
  EXPECT_FALSE(episode.Update(11, 59, config));  // weak: the episode begins
  EXPECT_EQ(episode.first_frame(), 11);
  EXPECT_FALSE(episode.Update(12, 20, config));
  EXPECT_EQ(episode.first_frame(), 11);           // still the first weak frame
  EXPECT_FALSE(episode.Update(13, 200, config));  // strong but too soon (kMinWeakFrames)
  EXPECT_FALSE(episode.Update(11 + kMinWeakFrames, 100, config));  // between the thresholds
  EXPECT_TRUE(episode.Update(11 + kMinWeakFrames, 120, config));
  episode.End();
  EXPECT_EQ(episode.first_frame(), -1);
  EXPECT_FALSE(episode.Update(30, 200, config));
}

TEST(WeakEpisode, EndsUncheckedAfterMaxCheckFramesAndIsOffWithReanchoringOff) {
  TrackingConfig config = Thresholds();
  WeakEpisode episode;
  EXPECT_FALSE(episode.Update(0, 10, config));
  EXPECT_TRUE(episode.Update(kMaxCheckFrames, 500, config));
  EXPECT_FALSE(episode.Update(kMaxCheckFrames + 1, 500, config));
  EXPECT_EQ(episode.first_frame(), -1);
  config.reanchoring = false;
  EXPECT_FALSE(episode.Update(200, 10, config));
  EXPECT_EQ(episode.first_frame(), -1);
}

// Keyframes at frames 0, 10, 20, 30, each creating two points: one verified static, one not.
Map MapOfFourKeyFrames() {
  Map map;
  for (int k = 0; k < 4; ++k) {
    KeyFrame keyframe;
    keyframe.frame_index = 10 * k;
    keyframe.T_world_camera.translation() = Eigen::Vector3d(0.1 * k, 0.0, 0.0);
    keyframe.measurements.T_camera_world = keyframe.T_world_camera.inverse();
    for (int j = 0; j < 2; ++j) {
      MapPoint point;
      point.created_frame = 10 * k;
      point.candidate = j == 1;
      point.p_world = Eigen::Vector3d(0.1 * k, j, 2.0);
      keyframe.points.push_back(map.AddPoint(point));
    }
    map.AddKeyFrame(keyframe, {2, 0, 10});  // two in the window, two archived
  }
  return map;
}

Eigen::Isometry3d SomeCorrection() {
  return Eigen::Translation3d(0.1, -0.2, 0.05) *
         Eigen::AngleAxisd(0.2, Eigen::Vector3d(1.0, 2.0, 0.5).normalized());
}

TEST(Reanchoring, OlderPointsAreTheVerifiedOnesMadeBeforeTheFrame) {
  Map map = MapOfFourKeyFrames();
  ASSERT_EQ(map.archived_keyframes().size(), 2u);
  EXPECT_EQ(VerifiedPointsMadeBefore(map, 25), (std::vector<PointId>{0, 2, 4}));
  map.Find(2)->marked = false;  // seen moving
  EXPECT_EQ(VerifiedPointsMadeBefore(map, 25), (std::vector<PointId>{0, 4}));
  EXPECT_TRUE(VerifiedPointsMadeBefore(map, 0).empty());
}

TEST(Reanchoring, CorrectionWorthApplyingByEitherBound) {
  const TrackingConfig config;  // 0.03 m, 1 deg
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(0.02, 0.0, 0.0);
  EXPECT_FALSE(CorrectionWorthApplying(T, config));
  T.translation() = Eigen::Vector3d(0.0, 0.031, 0.0);
  EXPECT_TRUE(CorrectionWorthApplying(T, config));
  const Eigen::Isometry3d R(Eigen::AngleAxisd(1.1 * M_PI / 180.0, Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(CorrectionWorthApplying(R, config));
}

TEST(Map, MoveMadeSinceMovesTheNewerKeyFramesAndPointsOnly) {
  Map map = MapOfFourKeyFrames();
  Map before = map;
  MapCorrection correction;
  correction.first_frame = 10;
  correction.T_new_old = SomeCorrection();
  EXPECT_EQ(map.corrections(), 0u);
  map.MoveMadeSince(correction);
  EXPECT_EQ(map.corrections(), 1u);
  for (int id = 0; id < 4; ++id) {
    const KeyFrame& moved = *map.FindKeyFrame(id);
    const KeyFrame& was = *before.FindKeyFrame(id);
    const Eigen::Isometry3d expected =
        id == 0 ? was.T_world_camera : correction.T_new_old * was.T_world_camera;
    EXPECT_TRUE(moved.T_world_camera.isApprox(expected, 1e-12)) << id;
    EXPECT_TRUE(moved.measurements.T_camera_world.isApprox(expected.inverse(), 1e-12)) << id;
  }
  for (PointId id = 0; id < 8; ++id) {
    const Eigen::Vector3d& was = before.Find(id)->p_world;
    const Eigen::Vector3d expected = id < 2 ? was : correction.T_new_old * was;
    EXPECT_TRUE(map.Find(id)->p_world.isApprox(expected, 1e-12)) << id;
  }
  const Eigen::Matrix3d R = correction.T_new_old.linear();
  EXPECT_TRUE(map.Find(7)->cov_world.isApprox(R * before.Find(7)->cov_world * R.transpose()));
}

TEST(Reanchoring, PartialCorrectionTurnsAboutThePivot) {
  MapCorrection correction;
  correction.T_new_old = SomeCorrection();
  correction.pivot_world = Eigen::Vector3d(1.0, 0.5, -2.0);
  EXPECT_TRUE(PartialCorrection(correction, 1.0).isApprox(correction.T_new_old, 1e-12));
  EXPECT_TRUE(PartialCorrection(correction, 0.0).isApprox(Eigen::Isometry3d::Identity(), 1e-12));
  const Eigen::Isometry3d half = PartialCorrection(correction, 0.5);
  EXPECT_NEAR(Eigen::AngleAxisd(half.rotation()).angle(), 0.1, 1e-12);
  const Eigen::Vector3d& c = correction.pivot_world;
  EXPECT_TRUE((half * c).isApprox(c + 0.5 * (correction.T_new_old * c - c), 1e-12));
}

TEST(Reanchoring, SharesGrowWithTheRotationVarianceOfThePoses) {
  Map map = MapOfFourKeyFrames();  // keyframes 1, 2, 3 made at frames 10, 20, 30
  const auto information = [](double rotation_variance) {
    Eigen::Matrix<double, 6, 6> info = Eigen::Matrix<double, 6, 6>::Identity() * 1e4;
    info.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() / (rotation_variance / 3.0);
    return info;
  };
  EXPECT_NEAR(RotationVariance(information(0.5)), 0.5, 1e-12);
  EXPECT_EQ(RotationVariance(Eigen::Matrix<double, 6, 6>::Zero()), 0.0);
  map.FindKeyFrame(1)->information = information(1.0);
  map.FindKeyFrame(2)->information = information(3.0);
  map.FindKeyFrame(3)->information = information(4.0);
  const std::map<int, double> share = CorrectionShares(map, 10, information(2.0));
  ASSERT_EQ(share.size(), 3u);  // keyframe 0 was made before the episode
  EXPECT_NEAR(share.at(1), 1.0 / 10.0, 1e-9);
  EXPECT_NEAR(share.at(2), 4.0 / 10.0, 1e-9);
  EXPECT_NEAR(share.at(3), 8.0 / 10.0, 1e-9);
  // Unknown information everywhere: equal steps up to the current frame.
  const std::map<int, double> equal =
      CorrectionShares(MapOfFourKeyFrames(), 10, Eigen::Matrix<double, 6, 6>::Zero());
  EXPECT_NEAR(equal.at(1), 0.25, 1e-12);
  EXPECT_NEAR(equal.at(3), 0.75, 1e-12);
  // The pivot: the camera of the newest keyframe made before the episode (frame 20).
  EXPECT_TRUE(CorrectionPivot(map, 25).isApprox(Eigen::Vector3d(0.2, 0.0, 0.0)));
  EXPECT_LT(CorrectionPivot(map, 0).norm(), 1e-12);  // none before: the oldest made since
}

TEST(Map, MoveMadeSinceMovesEachKeyFrameAndItsPointsByItsShare) {
  Map map = MapOfFourKeyFrames();
  Map before = map;
  MapCorrection correction;
  correction.first_frame = 20;
  correction.T_new_old = SomeCorrection();
  correction.pivot_world = Eigen::Vector3d(0.1, 0.0, 0.0);
  correction.share = {{2, 0.5}};  // keyframe 3 is not listed: all of it
  map.MoveMadeSince(correction);
  const Eigen::Isometry3d half = PartialCorrection(correction, 0.5);
  EXPECT_TRUE(map.FindKeyFrame(1)->T_world_camera.isApprox(before.FindKeyFrame(1)->T_world_camera));
  EXPECT_TRUE(map.FindKeyFrame(2)->T_world_camera.isApprox(
      half * before.FindKeyFrame(2)->T_world_camera, 1e-12));
  EXPECT_TRUE(map.FindKeyFrame(3)->T_world_camera.isApprox(
      correction.T_new_old * before.FindKeyFrame(3)->T_world_camera, 1e-12));
  EXPECT_TRUE(map.Find(4)->p_world.isApprox(half * before.Find(4)->p_world, 1e-12));  // frame 20
  EXPECT_TRUE(map.Find(7)->p_world.isApprox(correction.T_new_old * before.Find(7)->p_world, 1e-12));
  EXPECT_TRUE(map.Find(3)->p_world == before.Find(3)->p_world);  // frame 10: before the episode
}

// A loop correction: keyframes 0-2 get new poses, keyframe 3 (made while the correction was
// computed, not in it) moves with keyframe 2, every point with the keyframe that made it.
TEST(Map, CorrectKeyFramesMovesKeyFramesToTheirPosesAndPointsWithThem) {
  Map map = MapOfFourKeyFrames();
  Map before = map;
  std::map<int, Eigen::Isometry3d> corrected;
  for (int id = 0; id < 3; ++id) {
    const Eigen::Isometry3d T(Eigen::AngleAxisd(0.05 * id, Eigen::Vector3d::UnitY()));
    corrected[id] =
        Eigen::Translation3d(0.0, 0.02 * id, 0.0) * T * before.FindKeyFrame(id)->T_world_camera;
  }
  map.CorrectKeyFrames(corrected);
  EXPECT_EQ(map.corrections(), 1u);
  for (int id = 0; id < 3; ++id) {
    EXPECT_TRUE(map.FindKeyFrame(id)->T_world_camera.isApprox(corrected[id], 1e-12)) << id;
  }
  const Eigen::Isometry3d T_new_old_2 =
      corrected[2] * before.FindKeyFrame(2)->T_world_camera.inverse();
  EXPECT_TRUE(map.FindKeyFrame(3)->T_world_camera.isApprox(
      T_new_old_2 * before.FindKeyFrame(3)->T_world_camera, 1e-12));
  for (PointId id = 0; id < 8; ++id) {
    const int keyframe = static_cast<int>(id / 2);  // made with keyframe id / 2
    const Eigen::Isometry3d T_new_old =
        keyframe < 3 ? corrected[keyframe] * before.FindKeyFrame(keyframe)->T_world_camera.inverse()
                     : T_new_old_2;
    EXPECT_TRUE(map.Find(id)->p_world.isApprox(T_new_old * before.Find(id)->p_world, 1e-12)) << id;
  }
}

// A correction computed from older poses (loop closing reads the map, solves without the lock,
// then corrects) keeps what changed the keyframes since (a local BA run in between): each moves
// by corrected * before^-1 from where it is now, instead of to the absolute corrected pose.
TEST(Map, CorrectKeyFramesAppliesTheCorrectionToPosesChangedSinceItWasComputed) {
  Map map = MapOfFourKeyFrames();
  const Map read = map;  // what the correction was computed from
  std::map<int, Eigen::Isometry3d> corrected, before;
  for (int id = 0; id < 3; ++id) {
    before[id] = read.FindKeyFrame(id)->T_world_camera;
    corrected[id] = Eigen::Translation3d(0.0, 0.1, 0.0) * before[id];
  }
  // Local BA moves keyframe 1 by 2 cm after the read.
  const Eigen::Isometry3d refined = Eigen::Translation3d(0.02, 0.0, 0.0) * before[1];
  map.FindKeyFrame(1)->T_world_camera = refined;
  map.CorrectKeyFrames(corrected, before);
  EXPECT_TRUE(map.FindKeyFrame(1)->T_world_camera.isApprox(
      corrected[1] * before[1].inverse() * refined, 1e-12));
  EXPECT_FALSE(map.FindKeyFrame(1)->T_world_camera.isApprox(corrected[1], 1e-6));
  EXPECT_TRUE(map.FindKeyFrame(0)->T_world_camera.isApprox(corrected[0], 1e-12));  // unchanged
}

}  // namespace
}  // namespace dslam
