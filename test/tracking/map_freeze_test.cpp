// Map::Freeze: a loaded keyframe map used for localisation only stays as it was loaded (its
// keyframes and points are never erased, culled, moved or written), and the keyframes added
// after it are temporary: erased as soon as they are out of the window. Each test also runs the
// unfrozen map, which does change, so that the frozen expectations are not vacuous.
#include <vector>

#include <gtest/gtest.h>

#include "dslam/tracking/map.h"

namespace dslam {
namespace {

constexpr int kLoadedKeyFrames = 5;

// A loaded map (Map::FromContents, all archived) of kLoadedKeyFrames keyframes at frames 0, 10,
// ... with two points each; every point was visible 10 times and never found (unreliable).
Map LoadedMap() {
  Map map;
  for (int k = 0; k < kLoadedKeyFrames; ++k) {
    KeyFrame keyframe;
    keyframe.frame_index = 10 * k;
    keyframe.T_world_camera.translation() = Eigen::Vector3d(k, 0.0, 0.0);
    keyframe.measurements.T_camera_world = keyframe.T_world_camera.inverse();
    for (int i = 0; i < 2; ++i) {
      MapPoint point;
      point.p_world = Eigen::Vector3d(k, i, 2.0);
      point.created_frame = point.last_seen_frame = keyframe.frame_index;
      point.times_visible = 10;
      keyframe.points.push_back(map.AddPoint(point));
    }
    map.AddKeyFrame(keyframe, KeyFrameMapLimits::Newest(kLoadedKeyFrames));
  }
  return Map::FromContents(map.Contents());
}

// Adds a keyframe at frame `frame_index` that observes loaded point 0 and a new point.
void AddNewKeyFrame(int frame_index, const KeyFrameMapLimits& limits, Map* map) {
  MapPoint point;
  point.p_world = Eigen::Vector3d(0.0, 0.0, 3.0);
  point.created_frame = point.last_seen_frame = frame_index;
  KeyFrame keyframe;
  keyframe.frame_index = frame_index;
  keyframe.T_world_camera.translation() = Eigen::Vector3d(0.0, 1.0, 0.0);
  keyframe.points = {0, map->AddPoint(point)};
  map->AddKeyFrame(keyframe, limits);
}

// Whether every keyframe and point of `loaded` is in `map` with the same pose and position, bit
// for bit.
void ExpectLoadedPartUnchanged(const MapContents& loaded, const Map& map) {
  for (const KeyFrame& before : loaded.keyframes) {
    const KeyFrame* now = map.FindKeyFrame(before.id);
    ASSERT_NE(now, nullptr) << "keyframe " << before.id;
    EXPECT_EQ(now->T_world_camera.matrix(), before.T_world_camera.matrix()) << before.id;
    EXPECT_EQ(now->measurements.T_camera_world.matrix(),
              before.measurements.T_camera_world.matrix());
  }
  for (const MapPoint& before : loaded.points) {
    const MapPoint* now = map.Find(before.id);
    ASSERT_NE(now, nullptr) << "point " << before.id;
    EXPECT_EQ(now->p_world, before.p_world) << before.id;
    EXPECT_EQ(now->cov_world, before.cov_world) << before.id;
  }
}

TEST(MapFreeze, NewKeyFramesLeaveTheMapWithTheWindowAndLoadedOnesStay) {
  const KeyFrameMapLimits limits{2, 0, 3};  // a window of 2, a map of at most 3 keyframes
  Map frozen = LoadedMap();
  const MapContents loaded = frozen.Contents();
  frozen.Freeze();
  Map unfrozen = LoadedMap();
  for (int f = 100; f < 200; f += 10) {
    AddNewKeyFrame(f, limits, &frozen);
    AddNewKeyFrame(f, limits, &unfrozen);
  }
  // Frozen: the loaded keyframes and the window (the newest 2, ids 13 and 14).
  EXPECT_EQ(frozen.num_keyframes(), static_cast<size_t>(kLoadedKeyFrames) + 2);
  ASSERT_EQ(frozen.window().size(), 2u);
  EXPECT_EQ(frozen.window().front().id, kLoadedKeyFrames + 8);
  EXPECT_EQ(frozen.FindKeyFrame(kLoadedKeyFrames), nullptr);  // the first new one
  ExpectLoadedPartUnchanged(loaded, frozen);
  EXPECT_EQ(frozen.Find(0)->observing_keyframes, 1 + 2);  // its loaded keyframe and the window
  // Unfrozen: the cap of 3 erased the oldest, the loaded keyframes first.
  EXPECT_EQ(unfrozen.num_keyframes(), 3u);
  EXPECT_EQ(unfrozen.FindKeyFrame(0), nullptr);
}

TEST(MapFreeze, FrozenPointsAreNeitherCulledNorMovedNorWritable) {
  Map frozen = LoadedMap();
  const MapContents loaded = frozen.Contents();
  frozen.Freeze();
  EXPECT_TRUE(frozen.frozen());
  Map unfrozen = LoadedMap();
  MapCorrection correction;
  correction.first_frame = 0;
  correction.T_new_old.translation() = Eigen::Vector3d(0.5, 0.0, 0.0);
  std::map<int, Eigen::Isometry3d> corrected;
  for (int id = 0; id < kLoadedKeyFrames; ++id) corrected[id] = correction.T_new_old;
  for (Map* map : {&frozen, &unfrozen}) {
    map->MoveMadeSince(correction);
    map->CorrectKeyFrames(corrected);
  }
  ExpectLoadedPartUnchanged(loaded, frozen);
  EXPECT_EQ(frozen.FindWritable(0), nullptr);
  EXPECT_NE(unfrozen.Find(0)->p_world, loaded.points[0].p_world);
  EXPECT_NE(unfrozen.FindWritable(0), nullptr);
  // A copy of the window for the back end is frozen as the map is.
  frozen.SetWindowTo({0, 1});
  EXPECT_TRUE(frozen.WindowCopy().IsFrozenKeyFrame(1));
  EXPECT_TRUE(frozen.WindowCopy().IsFrozenPoint(3));
  // Every point is unreliable (found 0 of 10 times); only the unfrozen map culls its points.
  EXPECT_EQ(frozen.Cull(0, 0.5, 5), 0);
  EXPECT_EQ(unfrozen.Cull(0, 0.5, 5), 2 * kLoadedKeyFrames);
  ExpectLoadedPartUnchanged(loaded, frozen);
  frozen.Clear();
  EXPECT_FALSE(frozen.frozen());
}

TEST(MapFreeze, PointsAddedAfterTheFreezeAreWritableAndMove) {
  Map map = LoadedMap();
  map.Freeze();
  MapPoint point;
  point.created_frame = 100;
  const PointId added = map.AddPoint(point);
  EXPECT_FALSE(map.IsFrozenPoint(added));
  ASSERT_NE(map.FindWritable(added), nullptr);
  MapCorrection correction;
  correction.first_frame = 100;
  correction.T_new_old.translation() = Eigen::Vector3d(0.5, 0.0, 0.0);
  map.MoveMadeSince(correction);
  EXPECT_EQ(map.Find(added)->p_world, Eigen::Vector3d(0.5, 0.0, 0.0));
  EXPECT_EQ(map.Cull(200, 0.5, 5), 1);  // stale and unobserved
}

}  // namespace
}  // namespace dslam
