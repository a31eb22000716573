#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "dslam/tracking/map.h"

namespace dslam {
namespace {

// Three keyframes with two points each, the window the newest two (max 3 keyframes).
Map ThreeKeyFrames() {
  Map map;
  std::vector<PointId> ids;
  for (int i = 0; i < 6; ++i) {
    MapPoint point;
    point.p_world = Eigen::Vector3d(i, 0.5 * i, 2.0);
    point.created_frame = i;
    ids.push_back(map.AddPoint(point));
  }
  for (int k = 0; k < 3; ++k) {
    KeyFrame kf;
    kf.frame_index = 10 * k;
    kf.T_world_camera.translation() = Eigen::Vector3d(k, 0, 0);
    kf.points = {ids[2 * k], ids[2 * k + 1]};
    map.AddKeyFrame(kf, {2, 0, 3});
  }
  return map;
}

TEST(MapContents, ContentsListEveryPointAndKeyFrameById) {
  const Map map = ThreeKeyFrames();
  ASSERT_EQ(map.archived_keyframes().size(), 1u);
  const MapContents contents = map.Contents();
  ASSERT_EQ(contents.points.size(), 6u);
  ASSERT_EQ(contents.keyframes.size(), 3u);
  for (size_t i = 0; i < 6; ++i) EXPECT_EQ(contents.points[i].id, static_cast<PointId>(i));
  for (int k = 0; k < 3; ++k) EXPECT_EQ(contents.keyframes[k].id, k);
}

TEST(MapContents, FromContentsKeepsIdsArchivesKeyFramesAndCountsObservers) {
  const Map original = ThreeKeyFrames();
  Map map = Map::FromContents(original.Contents());
  EXPECT_EQ(map.size(), 6u);
  EXPECT_EQ(map.num_keyframes(), 3u);
  EXPECT_TRUE(map.window().empty());
  EXPECT_EQ(map.next_point_id(), original.next_point_id());
  ASSERT_NE(map.Find(3), nullptr);
  EXPECT_EQ(map.Find(3)->p_world, Eigen::Vector3d(3, 1.5, 2.0));
  EXPECT_EQ(map.Find(3)->observing_keyframes, 1);
  ASSERT_NE(map.FindKeyFrame(2), nullptr);
  EXPECT_EQ(map.FindKeyFrame(2)->frame_index, 20);
  // New keyframes and points continue after the loaded ids.
  EXPECT_EQ(map.AddPoint(MapPoint()), 6);
  EXPECT_EQ(map.AddKeyFrame(KeyFrame(), {2, 0, 10}).id, 3);
}

TEST(MapContents, FromContentsDropsReferencesToMissingPoints) {
  MapContents contents = ThreeKeyFrames().Contents();
  contents.points.erase(contents.points.begin());  // point 0, listed by keyframe 0
  const Map map = Map::FromContents(contents);
  EXPECT_EQ(map.FindKeyFrame(0)->points, (std::vector<PointId>{1}));
}

TEST(MapContents, RepeatedOrNegativeIdsAreRefused) {
  MapContents contents = ThreeKeyFrames().Contents();
  contents.points[1].id = 0;
  EXPECT_THROW(Map::FromContents(contents), std::invalid_argument);
  contents = ThreeKeyFrames().Contents();
  contents.keyframes[2].id = 1;
  EXPECT_THROW(Map::FromContents(contents), std::invalid_argument);
  contents = ThreeKeyFrames().Contents();
  contents.keyframes[0].id = -1;
  EXPECT_THROW(Map::FromContents(contents), std::invalid_argument);
}

TEST(MapContents, IdsWhoseNextWouldOverflowAreRefused) {
  MapContents contents = ThreeKeyFrames().Contents();
  contents.keyframes[2].id = std::numeric_limits<int>::max();
  const auto message = [](const MapContents& c) {
    try {
      Map::FromContents(c);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_EQ(message(contents),
            "keyframe id 2147483647 is the largest int: the next keyframe's id would overflow");
  contents.keyframes[2].id = std::numeric_limits<int>::max() - 1;  // the next id still fits
  EXPECT_NO_THROW(Map::FromContents(contents));
  contents = ThreeKeyFrames().Contents();
  contents.points[5].id = std::numeric_limits<PointId>::max();
  EXPECT_EQ(message(contents),
            "map point id 9223372036854775807 is the largest PointId: the next point's id would "
            "overflow");
}

TEST(MapContents, SetWindowToChoosesTheWindowAndErasesNothing) {
  Map map = Map::FromContents(ThreeKeyFrames().Contents());
  map.SetWindowTo({2, 0, 7});
  ASSERT_EQ(map.window().size(), 2u);
  EXPECT_EQ(map.window()[0].id, 0);
  EXPECT_EQ(map.window()[1].id, 2);
  EXPECT_EQ(map.first_recent_keyframe(), 0u);
  EXPECT_EQ(map.num_keyframes(), 3u);
  map.SetWindowTo({1});
  EXPECT_EQ(map.window().size(), 1u);
  EXPECT_EQ(map.num_keyframes(), 3u);
  EXPECT_EQ(map.LocalPoints({}), (std::vector<PointId>{2, 3}));
}

}  // namespace
}  // namespace dslam
