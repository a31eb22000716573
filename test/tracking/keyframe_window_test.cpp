// The keyframe map: window choice by covisibility and nearby cameras, archive, redundancy culling
// and the cap (Map::AddKeyFrame, SelectKeyFrameWindow).
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/tracking/keyframe_window.h"
#include "dslam/tracking/map.h"

namespace dslam {
namespace {

std::vector<PointId> NewPoints(Map* map, int n) {
  std::vector<PointId> ids;
  for (int i = 0; i < n; ++i) ids.push_back(map->AddPoint(MapPoint()));
  return ids;
}

KeyFrame KeyFrameAt(double x_m, double yaw_deg, std::vector<PointId> points) {
  KeyFrame keyframe;
  keyframe.T_world_camera.translate(Eigen::Vector3d(x_m, 0.0, 0.0));
  keyframe.T_world_camera.rotate(
      Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitY()));
  keyframe.points = std::move(points);
  return keyframe;
}

std::vector<int> WindowIds(const Map& map) {
  std::vector<int> ids;
  for (const KeyFrame& keyframe : map.window()) ids.push_back(keyframe.id);
  return ids;
}

// Keyframes 0-5 walk away along x (1 m apart), each with its own 30 points.
Map WalkAway(const KeyFrameMapLimits& limits, std::vector<std::vector<PointId>>* points) {
  Map map;
  for (int k = 0; k < 6; ++k) {
    points->push_back(NewPoints(&map, 30));
    map.AddKeyFrame(KeyFrameAt(k, 0.0, points->back()), limits);
  }
  return map;
}

TEST(KeyFrameMap, NewestKeyFramesAloneMatchTheOldWindow) {
  std::vector<std::vector<PointId>> points;
  Map map = WalkAway(KeyFrameMapLimits::Newest(3), &points);
  EXPECT_EQ(WindowIds(map), (std::vector<int>{3, 4, 5}));
  EXPECT_EQ(map.num_keyframes(), 3u);
  EXPECT_EQ(map.first_recent_keyframe(), 0u);
  EXPECT_EQ(map.Find(points[0][0])->observing_keyframes, 0);
  EXPECT_EQ(map.Find(points[5][0])->observing_keyframes, 1);
}

TEST(KeyFrameMap, AnOldKeyFrameSharingPointsRejoinsTheWindow) {
  const KeyFrameMapLimits limits{3, 2, 100};
  std::vector<std::vector<PointId>> points;
  Map map = WalkAway(limits, &points);
  EXPECT_EQ(WindowIds(map), (std::vector<int>{3, 4, 5}));
  EXPECT_EQ(map.archived_keyframes().size(), 3u);
  // Back at keyframe 1's place, but 0.5 m off (not nearby), seeing 20 of its points.
  std::vector<PointId> seen(points[1].begin(), points[1].begin() + kMinCovisiblePoints + 5);
  map.AddKeyFrame(KeyFrameAt(1.5, 0.0, seen), limits);
  EXPECT_EQ(WindowIds(map), (std::vector<int>{1, 4, 5, 6}));
  EXPECT_EQ(map.first_recent_keyframe(), 1u);
  const std::vector<PointId> local = map.LocalPoints({});
  EXPECT_NE(std::find(local.begin(), local.end(), points[1].back()), local.end());
  ASSERT_NE(map.FindKeyFrame(3), nullptr);  // archived, still found
  EXPECT_EQ(map.FindKeyFrame(3)->id, 3);
}

TEST(KeyFrameMap, ANearbyKeyFrameWithoutSharedPointsRejoinsTheWindow) {
  const KeyFrameMapLimits limits{3, 2, 100};
  std::vector<std::vector<PointId>> points;
  Map map = WalkAway(limits, &points);
  // Near keyframe 0 (0.1 m, 10 deg) with new points only; keyframe 2 is 0.2 m off but turned
  // away by 30 deg: not nearby.
  map.AddKeyFrame(KeyFrameAt(0.1, 10.0, NewPoints(&map, 30)), limits);
  EXPECT_EQ(WindowIds(map), (std::vector<int>{0, 4, 5, 6}));
  map.AddKeyFrame(KeyFrameAt(2.2, 30.0, NewPoints(&map, 30)), limits);
  const std::vector<int> window = WindowIds(map);
  EXPECT_EQ(std::count(window.begin(), window.end(), 2), 0);
}

TEST(KeyFrameMap, TheCapErasesTheOldestArchivedKeyFrames) {
  const KeyFrameMapLimits limits{2, 1, 4};
  std::vector<std::vector<PointId>> points;
  Map map = WalkAway(limits, &points);
  EXPECT_EQ(map.num_keyframes(), 4u);
  EXPECT_EQ(map.FindKeyFrame(0), nullptr);
  EXPECT_EQ(map.FindKeyFrame(1), nullptr);
  ASSERT_NE(map.FindKeyFrame(2), nullptr);
  // Points of erased keyframes are observed by none and go at the next cull; the others stay.
  EXPECT_EQ(map.Find(points[0][0])->observing_keyframes, 0);
  EXPECT_EQ(map.Cull(100, 0.25, 8), 60);
  EXPECT_EQ(map.Find(points[1][0]), nullptr);
  EXPECT_NE(map.Find(points[2][0]), nullptr);
}

TEST(KeyFrameMap, ARedundantKeyFrameIsErasedWhenItLeavesTheWindow) {
  const KeyFrameMapLimits limits{2, 0, 100};
  Map map;
  const std::vector<PointId> shared = NewPoints(&map, 30);
  // Keyframes 0-4 see the same points: when one leaves the window, 4 others observe them.
  for (int k = 0; k < 5; ++k) map.AddKeyFrame(KeyFrameAt(0.0, 0.0, shared), limits);
  EXPECT_EQ(WindowIds(map), (std::vector<int>{3, 4}));
  EXPECT_LE(map.archived_keyframes().size(), 1u);
  // One with points of its own is kept.
  map.AddKeyFrame(KeyFrameAt(1.0, 0.0, NewPoints(&map, 30)), limits);
  map.AddKeyFrame(KeyFrameAt(2.0, 0.0, NewPoints(&map, 30)), limits);
  map.AddKeyFrame(KeyFrameAt(3.0, 0.0, NewPoints(&map, 30)), limits);
  EXPECT_NE(map.FindKeyFrame(5), nullptr);
}

}  // namespace
}  // namespace dslam
