// The free-space check with known answers: a view's votes, and a transient object seen in front
// of a wall by one keyframe and through by another, in either order, removed from the map.
#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "dslam/mapping/free_space.h"
#include "dslam/mapping/static_mapper.h"
#include "mapping/mapping_scenes.h"

namespace dslam {
namespace {

using test::MakeKeyFrame;
using test::MapTestConfig;
using test::Wall;
using test::WallWithBox;

// Margin 0.1 m + 3% of the depth, points 0.3 - 4 m from the camera.
FreeSpaceTolerance Tolerance() {
  Config config = MapTestConfig();
  config.map.free_space_margin_m = 0.1;
  config.map.free_space_margin_ratio = 0.03;
  return FreeSpaceTolerance::From(config.map, 0.3, 4.0);
}

TEST(DepthView, VotesOnPointsAlongTheRays) {
  const KeyFrameRecord wall = MakeKeyFrame(0, Wall(3.0f));
  const DepthView view(wall.frame, Eigen::Isometry3d::Identity(), 4, 0.3);
  const FreeSpaceTolerance tolerance = Tolerance();
  // Straight ahead; the margin at 2.9 m is 0.1 + 0.087 m.
  EXPECT_EQ(view.Vote(Eigen::Vector3f(0, 0, 3.0f), tolerance), Visibility::kSupport);
  EXPECT_EQ(view.Vote(Eigen::Vector3f(0, 0, 2.85f), tolerance), Visibility::kSupport);
  EXPECT_EQ(view.Vote(Eigen::Vector3f(0, 0, 2.7f), tolerance), Visibility::kSeeThrough);
  EXPECT_EQ(view.Vote(Eigen::Vector3f(0, 0, 1.0f), tolerance), Visibility::kSeeThrough);
  EXPECT_EQ(view.Vote(Eigen::Vector3f(0, 0, 3.5f), tolerance), Visibility::kNoVote);  // behind
  EXPECT_EQ(view.Vote(Eigen::Vector3f(0, 0, 0.2f), tolerance), Visibility::kNoVote);  // too near
  EXPECT_EQ(view.Vote(Eigen::Vector3f(0, 0, -1.0f), tolerance), Visibility::kNoVote);
  EXPECT_EQ(view.Vote(Eigen::Vector3f(5.0f, 0, 1.0f), tolerance), Visibility::kNoVote);  // outside
  // The same point from a view moved 1 m back: 1 m farther from it.
  DepthView moved = view;
  Eigen::Isometry3d back = Eigen::Isometry3d::Identity();
  back.translation().z() = -1.0;
  moved.set_pose(back);
  EXPECT_EQ(moved.Vote(Eigen::Vector3f(0, 0, 2.0f), tolerance), Visibility::kSupport);
  EXPECT_EQ(moved.Vote(Eigen::Vector3f(0, 0, 3.0f), tolerance), Visibility::kNoVote);
}

TEST(DepthView, DepthEdgesAndMissingDepthGiveNoSeeThrough) {
  // A box at 1.5 m over u in [300, 340): points just beside it, at the wall's depth minus 1 m,
  // are next to the box's nearer depth within a block: occluded, not seen through.
  const KeyFrameRecord keyframe = MakeKeyFrame(0, WallWithBox(3.0f, 1.5f, 300, 340, 0, 480));
  const DepthView view(keyframe.frame, Eigen::Isometry3d::Identity(), 4, 0.3);
  const auto at_pixel = [](double u, double z) {
    return Eigen::Vector3f(static_cast<float>((u - 320.25) * z / 505.0), 0.0f,
                           static_cast<float>(z));
  };
  EXPECT_EQ(view.Vote(at_pixel(298, 2.0), Tolerance()), Visibility::kNoVote);
  EXPECT_EQ(view.Vote(at_pixel(250, 2.0), Tolerance()), Visibility::kSeeThrough);
  const KeyFrameRecord empty = MakeKeyFrame(1, Wall(0.0f));
  const DepthView none(empty.frame, Eigen::Isometry3d::Identity(), 4, 0.3);
  EXPECT_EQ(none.Vote(at_pixel(320, 2.0), Tolerance()), Visibility::kNoVote);
}

TEST(DepthView, FromBlockDepthsTakesTheNearestOfTheNeighbours) {
  // Blocks of 4 px of a wall at 3 m: block column 50 (u 200-203) at 1.5 m, column 100 (u 400-403)
  // and columns 120-130 (u 480-523) without depth.
  const KeyFrameRecord wall = MakeKeyFrame(0, Wall(3.0f));
  const float inf = std::numeric_limits<float>::infinity();
  cv::Mat blocks(120, 160, CV_32FC1, cv::Scalar(3.0f));
  blocks.col(50).setTo(1.5f);
  blocks.col(100).setTo(inf);
  blocks.colRange(120, 131).setTo(inf);
  const DepthView view(wall.frame.camera, Eigen::Isometry3d::Identity(), 4, blocks);
  const auto at_pixel = [](double u, double z) {
    return Eigen::Vector3f(static_cast<float>((u - 320.25) * z / 505.0), 0.0f,
                           static_cast<float>(z));
  };
  EXPECT_EQ(view.Vote(at_pixel(250, 2.0), Tolerance()), Visibility::kSeeThrough);
  EXPECT_EQ(view.Vote(at_pixel(250, 3.0), Tolerance()), Visibility::kSupport);
  EXPECT_EQ(view.Vote(at_pixel(206, 2.0), Tolerance()), Visibility::kNoVote);  // next to 1.5 m
  EXPECT_EQ(view.Vote(at_pixel(196, 2.0), Tolerance()), Visibility::kNoVote);
  EXPECT_EQ(view.Vote(at_pixel(190, 2.0), Tolerance()), Visibility::kSeeThrough);
  EXPECT_EQ(view.Vote(at_pixel(402, 2.0), Tolerance()), Visibility::kSeeThrough);  // neighbours
  EXPECT_EQ(view.Vote(at_pixel(502, 2.0), Tolerance()), Visibility::kNoVote);      // none around
}

// Points of `cloud` nearer than 2.5 m (the box at 1.51 m; the wall is at 3.01 m: depths off the
// 5 cm voxel boundaries).
size_t BoxPoints(const ColouredCloud& cloud) {
  size_t n = 0;
  for (const ColouredPoint& point : cloud) n += point.p.z() < 2.5f;
  return n;
}

// A box at 1.51 m in front of a wall at 3.01 m, in one of two keyframes from nearby poses; the
// other sees the wall there. Returns the fused map (both keyframes left the window).
ColouredCloud FuseBoxAndWall(bool box_first, bool free_space_check) {
  Config config = MapTestConfig();
  config.map.free_space_check = free_space_check;
  StaticMapper mapper(config);
  Eigen::Isometry3d shifted = Eigen::Isometry3d::Identity();
  shifted.translation().x() = 0.1;
  const KeyFrameRecord with_box =
      MakeKeyFrame(box_first ? 0 : 1, WallWithBox(3.01f, 1.51f, 250, 390, 180, 300));
  const KeyFrameRecord wall_only = MakeKeyFrame(box_first ? 1 : 0, Wall(3.01f), shifted);
  const KeyFrameRecord& first = box_first ? with_box : wall_only;
  const KeyFrameRecord& second = box_first ? wall_only : with_box;
  mapper.OnKeyFrames({first}, test::WindowOf({first}));
  mapper.OnKeyFrames({second}, test::WindowOf({first, second}));
  EXPECT_EQ(mapper.stats().window_keyframes, 2);
  EXPECT_GT(BoxPoints(mapper.Cloud()), 0u);  // not yet checked while in the window
  mapper.OnKeyFrames({}, {});                // both leave the window
  EXPECT_EQ(mapper.stats().window_keyframes, 0);
  return mapper.Cloud();
}

// The 5 cm voxels of the box's samples (pixels 2, 6, ... within it), from the pinhole model.
size_t BoxVoxels() {
  std::set<std::pair<int, int>> keys;
  for (int v = 182; v < 300; v += 4) {
    for (int u = 250; u < 390; u += 4) {
      keys.emplace(std::floor((u - 320.25) * 1.51 / 505.0 / 0.05),
                   std::floor((v - 240.25) * 1.51 / 505.0 / 0.05));
    }
  }
  return keys.size();
}

TEST(StaticMapper, FreeSpaceCheckRemovesAnObjectALaterKeyframeSeesThrough) {
  // Box first: the wall-only keyframe, fused after it, carves the box's voxels.
  EXPECT_EQ(BoxPoints(FuseBoxAndWall(true, false)), BoxVoxels());
  EXPECT_EQ(BoxPoints(FuseBoxAndWall(true, true)), 0u);
}

TEST(StaticMapper, FreeSpaceCheckRemovesAnObjectAnEarlierKeyframeSawThrough) {
  // Wall first: its view votes on the box's points as they are fused.
  EXPECT_EQ(BoxPoints(FuseBoxAndWall(false, false)), BoxVoxels());
  EXPECT_EQ(BoxPoints(FuseBoxAndWall(false, true)), 0u);
}

TEST(StaticMapper, FreeSpaceCheckKeepsTheStaticWall) {
  // The wall behind the box is seen by the wall-only keyframe: the map holds the whole wall in
  // either order, as many voxels as the two walls fused without any check and without the box.
  Config config = MapTestConfig();
  config.map.free_space_check = false;
  StaticMapper walls(config);
  Eigen::Isometry3d shifted = Eigen::Isometry3d::Identity();
  shifted.translation().x() = 0.1;
  walls.OnKeyFrames({MakeKeyFrame(0, Wall(3.01f)), MakeKeyFrame(1, Wall(3.01f), shifted)}, {});
  const size_t wall_voxels = walls.stats().voxels;
  for (const bool box_first : {true, false}) {
    const ColouredCloud cloud = FuseBoxAndWall(box_first, true);
    EXPECT_EQ(cloud.size(), wall_voxels) << "box first " << box_first;
  }
}

}  // namespace
}  // namespace dslam
