// StaticMapper with known answers: pose corrections move the window's points, fused points stay
// where their final pose put them, resets, the dynamic mask, PCD files.
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "dslam/mapping/keyframe_mask.h"
#include "dslam/mapping/static_mapper.h"
#include "mapping/mapping_scenes.h"

namespace dslam {
namespace {

using test::kPlaneDepthM;
using test::MakeKeyFrame;
using test::MapTestConfig;
using test::Wall;
using test::WindowOf;

Eigen::Vector3f MeanOf(const ColouredCloud& cloud) {
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  for (const ColouredPoint& point : cloud) sum += point.p;
  return sum / static_cast<float>(cloud.size());
}

TEST(StaticMapper, CorrectionsMoveTheWindowsPointsUntilTheKeyframeLeavesIt) {
  StaticMapper mapper(MapTestConfig());
  const KeyFrameRecord keyframe = MakeKeyFrame(0, Wall(kPlaneDepthM));
  mapper.OnKeyFrames({keyframe}, WindowOf({keyframe}));
  const ColouredCloud before = mapper.Cloud();
  ASSERT_FALSE(before.empty());
  EXPECT_EQ(mapper.stats().voxels, 0u);  // nothing fused for good yet
  // The back end moves the keyframe 0.3 m up (-y, optical frame) and 0.2 m forward.
  Eigen::Isometry3d corrected = Eigen::Isometry3d::Identity();
  corrected.translation() = Eigen::Vector3d(0.0, -0.3, 0.2);
  const uint64_t revision = mapper.revision();
  mapper.OnKeyFrames({}, {{0, corrected}});
  EXPECT_GT(mapper.revision(), revision);
  const ColouredCloud moved = mapper.Cloud();
  for (const ColouredPoint& point : moved) EXPECT_NEAR(point.p.z(), kPlaneDepthM + 0.2, 1e-5);
  const Eigen::Vector3f shift = MeanOf(moved) - MeanOf(before);
  EXPECT_NEAR(shift.y(), -0.3f, 0.03f);  // one voxel's worth: the grid cuts the plane anew
  // It leaves the window: fused at the corrected pose, which nothing changes any more.
  mapper.OnKeyFrames({}, {});
  EXPECT_EQ(mapper.stats().voxels, moved.size());
  mapper.OnKeyFrames({}, {{0, Eigen::Isometry3d::Identity()}});  // an unknown keyframe's pose
  for (const ColouredPoint& point : mapper.Cloud()) {
    EXPECT_NEAR(point.p.z(), kPlaneDepthM + 0.2, 1e-5);
  }
}

TEST(StaticMapper, ResetWithANewWorldEmptiesTheMapAndKeepPoseFusesTheWindow) {
  StaticMapper mapper(MapTestConfig());
  const KeyFrameRecord first = MakeKeyFrame(0, Wall(kPlaneDepthM));
  mapper.OnKeyFrames({first}, {});
  const KeyFrameRecord second = MakeKeyFrame(1, Wall(kPlaneDepthM));
  mapper.OnKeyFrames({second}, WindowOf({second}));
  ASSERT_EQ(mapper.stats().window_keyframes, 1);
  const size_t voxels = mapper.stats().voxels;
  mapper.OnReset(ResetMode::kKeepPose);  // the world frame goes on: the window is fused
  EXPECT_EQ(mapper.stats().window_keyframes, 0);
  EXPECT_EQ(mapper.stats().fused_keyframes, 2);
  EXPECT_EQ(mapper.stats().voxels, voxels);  // the same plane: hits, no new voxels
  mapper.OnReset(ResetMode::kNewWorld);
  const StaticMapStats stats = mapper.stats();
  EXPECT_EQ(stats.voxels, 0u);
  EXPECT_EQ(stats.fused_keyframes, 0);
  EXPECT_TRUE(mapper.Cloud().empty());
  // The new world's keyframes fuse as before.
  mapper.OnKeyFrames({MakeKeyFrame(2, Wall(kPlaneDepthM))}, {});
  EXPECT_EQ(mapper.stats().voxels, voxels);
}

TEST(DiscMask, MasksDiscsAroundUnmarkedPointsOnly) {
  std::vector<ObservedPoint> points(2);
  points[0].uv_raw = Eigen::Vector2d(100, 100);
  points[0].is_static = false;
  points[1].uv_raw = Eigen::Vector2d(400, 300);
  points[1].is_static = true;
  const cv::Mat mask = DiscMask(points, cv::Size(640, 480), 10);
  EXPECT_EQ(mask.at<uint8_t>(100, 100), 255);
  EXPECT_EQ(mask.at<uint8_t>(100, 110), 255);  // on the circle
  EXPECT_EQ(mask.at<uint8_t>(100, 112), 0);
  EXPECT_EQ(mask.at<uint8_t>(300, 400), 0);  // static point
  // A filled disc of radius 10 covers about pi 10^2 = 314 pixels.
  EXPECT_NEAR(cv::countNonZero(mask), 314, 30);
  EXPECT_EQ(cv::countNonZero(DiscMask(points, cv::Size(640, 480), 0)), 1);
}

TEST(StaticMapper, DynamicMasksLeaveTheMovingPixelsOut) {
  KeyFrameRecord keyframe = MakeKeyFrame(0, Wall(kPlaneDepthM));
  ObservedPoint mover;
  mover.uv_raw = Eigen::Vector2d(320, 240);
  mover.is_static = false;
  keyframe.points = {mover};
  Config config = MapTestConfig();
  config.map.mask_radius_px = 60;
  const auto near_mover = [](const ColouredCloud& cloud) {
    size_t n = 0;  // within 0.15 m of the mover's ray on the plane (60 px = 0.24 m)
    for (const ColouredPoint& point : cloud) n += point.p.head<2>().norm() < 0.15f;
    return n;
  };
  StaticMapper masked(config);
  masked.OnKeyFrames({keyframe}, {});
  EXPECT_EQ(near_mover(masked.Cloud()), 0u);
  config.map.dynamic_masks = false;
  StaticMapper unmasked(config);
  unmasked.OnKeyFrames({keyframe}, {});
  EXPECT_GT(near_mover(unmasked.Cloud()), 20u);  // about pi (0.15 / 0.05)^2 = 28 voxels
  EXPECT_GT(unmasked.stats().voxels, masked.stats().voxels);
}

TEST(Pcd, WritesAndReadsColouredPoints) {
  const std::string path = ::testing::TempDir() + "dslam_map_test.pcd";
  const ColouredCloud cloud = {{Eigen::Vector3f(1.5f, -2.25f, 3.0f), 255, 0, 10},
                               {Eigen::Vector3f(0.0f, 0.125f, -7.5f), 1, 2, 3}};
  WritePcd(path, cloud);
  std::ifstream in(path);
  std::string line;
  bool fields = false;
  while (std::getline(in, line)) fields |= line == "FIELDS x y z rgb";
  EXPECT_TRUE(fields);
  const ColouredCloud read = ReadPcd(path);
  ASSERT_EQ(read.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(read[i].p, cloud[i].p);
    EXPECT_EQ(read[i].r, cloud[i].r);
    EXPECT_EQ(read[i].g, cloud[i].g);
    EXPECT_EQ(read[i].b, cloud[i].b);
  }
  WritePcd(path, {});  // an empty map is a valid file
  EXPECT_TRUE(ReadPcd(path).empty());
  std::remove(path.c_str());
  EXPECT_THROW(WritePcd("/nonexistent/folder/map.pcd", cloud), std::runtime_error);
  EXPECT_THROW(ReadPcd("/nonexistent/folder/map.pcd"), std::runtime_error);
}

}  // namespace
}  // namespace dslam
