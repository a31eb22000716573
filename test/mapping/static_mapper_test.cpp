// StaticMapper with known answers: pose corrections move the window's points, fused points stay
// where their final pose put them, resets, the dynamic mask's pixels left out, PCD files.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "dslam/mapping/coloured_cloud.h"
#include "dslam/mapping/dynamic_mask.h"
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

TEST(StaticMapper, RaysGiveTheFusedPointsAndEveryKeptKeyFramesView) {
  // The grid's input: a keyframe still in the window gives its view (rays) but no obstacle
  // points (a walker there has not been seen through yet); fused, its points join.
  StaticMapper mapper(MapTestConfig());
  const KeyFrameRecord keyframe = MakeKeyFrame(0, Wall(kPlaneDepthM));
  mapper.OnKeyFrames({keyframe}, WindowOf({keyframe}));
  StaticMapRays rays = mapper.Rays();
  EXPECT_TRUE(rays.points_world.empty());
  ASSERT_EQ(rays.views.size(), 1u);
  EXPECT_FALSE(rays.views[0].points_world.empty());
  EXPECT_EQ(rays.views[0].camera_world, Eigen::Vector3d::Zero());
  for (const Eigen::Vector3f& p : rays.views[0].points_world) {
    EXPECT_NEAR(p.z(), kPlaneDepthM, 0.05);  // the wall, in the world (the keyframe's pose)
  }
  mapper.FuseWindow();
  rays = mapper.Rays();
  EXPECT_EQ(rays.points_world.size(), mapper.Cloud().size());
  ASSERT_EQ(rays.views.size(), 1u);  // kept for re-fusion: still a view
}

TEST(StaticMapper, ALoopCorrectionReFusesFusedKeyFramesAtTheirCorrectedPoses) {
  StaticMapper mapper(MapTestConfig());
  const KeyFrameRecord first = MakeKeyFrame(0, Wall(kPlaneDepthM));
  const KeyFrameRecord second = MakeKeyFrame(1, Wall(kPlaneDepthM));
  mapper.OnKeyFrames({first, second}, {});  // both fused for good at once
  const size_t voxels = mapper.stats().voxels;
  ASSERT_GT(voxels, 0u);
  // Keyframe 1 saw the same wall from the same pose: one wall. The loop correction says it was
  // 0.4 m further forward (and keyframe 0 stays): keyframe 1's points move with it.
  Eigen::Isometry3d corrected = Eigen::Isometry3d::Identity();
  corrected.translation() = Eigen::Vector3d(0.0, 0.0, 0.4);
  const uint64_t revision = mapper.revision();
  mapper.OnCorrection({{0, Eigen::Isometry3d::Identity()}, {1, corrected}});
  EXPECT_GT(mapper.revision(), revision);
  EXPECT_EQ(mapper.stats().corrections, 1);
  const auto depths_cm = [&mapper] {  // the walls' depths in the map [cm]
    std::set<long> depths;
    for (const ColouredPoint& point : mapper.Cloud())
      depths.insert(std::lround(100.0 * point.p.z()));
    return depths;
  };
  const std::set<long> two_walls{std::lround(100.0 * kPlaneDepthM),
                                 std::lround(100.0 * (kPlaneDepthM + 0.4))};
  EXPECT_EQ(depths_cm(), two_walls);
  // Corrected back: one wall again, as many voxels as before.
  mapper.OnCorrection({{0, Eigen::Isometry3d::Identity()}, {1, Eigen::Isometry3d::Identity()}});
  EXPECT_EQ(mapper.stats().voxels, voxels);
  EXPECT_EQ(depths_cm(), std::set<long>{std::lround(100.0 * kPlaneDepthM)});
  // Keyframe 1 is not in this correction (the map erased it): it moves with keyframe 0.
  mapper.OnCorrection({{0, corrected}});
  EXPECT_EQ(depths_cm(), std::set<long>{std::lround(100.0 * (kPlaneDepthM + 0.4))});
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

// The 5 cm voxels of the samples (pixels 2, 6, ...) of a plane at `depth_m` inside (or outside)
// the pixel box [250, 390) x [180, 300), from the pinhole model.
size_t VoxelsOfSamples(double depth_m, bool inside_box) {
  std::set<std::tuple<int, int, int>> keys;
  for (int v = 2; v < 480; v += 4) {
    for (int u = 2; u < 640; u += 4) {
      if ((u >= 250 && u < 390 && v >= 180 && v < 300) != inside_box) continue;
      keys.emplace(std::floor((u - 320.25) * depth_m / 505.0 / 0.05),
                   std::floor((v - 240.25) * depth_m / 505.0 / 0.05), std::floor(depth_m / 0.05));
    }
  }
  return keys.size();
}

TEST(KeyFrameCloud, MaskedPixelsBackProjectToThePeopleOnly) {
  // The obstacles of a frame: a mask of 10 px cells over the box [250, 390) x [180, 300) in front
  // of the wall gives the box's points only, one per 5 cm voxel, at the box's depth.
  const KeyFrameRecord keyframe =
      MakeKeyFrame(0, test::WallWithBox(kPlaneDepthM, 1.51f, 250, 390, 180, 300));
  DynamicMask mask;
  mask.decimation = 10;
  mask.labels = cv::Mat::zeros(48, 64, CV_16UC1);
  mask.labels(cv::Rect(25, 18, 14, 12)).setTo(1);  // cells of pixels [250, 390) x [180, 300)
  mask.regions.resize(1);
  mask.regions[0].label = 1;
  EXPECT_EQ(cv::countNonZero(PixelMask(mask, cv::Size(640, 480))), 140 * 120);
  BackProjection options;
  options.voxel_size_m = 0.05;
  const ColouredCloud people = BackProjectMasked(keyframe.frame, mask, options);
  ASSERT_FALSE(people.empty());
  EXPECT_EQ(people.size(), VoxelsOfSamples(1.51, true));
  for (const ColouredPoint& point : people) EXPECT_NEAR(point.p.z(), 1.51f, 0.05f);
  EXPECT_TRUE(BackProjectMasked(keyframe.frame, DynamicMask(), options).empty());  // nobody
}

TEST(StaticMapper, DynamicMasksLeaveTheMovingPixelsOut) {
  // A person-sized box at 1.51 m in front of the plane, with nine unmarked points on it: the mask
  // grows over the box and stops at its depth edge.
  KeyFrameRecord keyframe =
      MakeKeyFrame(0, test::WallWithBox(kPlaneDepthM, 1.51f, 250, 390, 180, 300));
  for (int i = 0; i < 9; ++i) {
    ObservedPoint mover;
    mover.id = i;
    mover.uv_raw = Eigen::Vector2d(280 + 40 * (i % 3), 200 + 40 * (i / 3));
    mover.is_static = false;
    keyframe.points.push_back(mover);
  }
  const cv::Mat mask = DynamicPixelMask(keyframe, MapTestConfig().dynamic_mask);
  EXPECT_EQ(mask.at<uint8_t>(240, 320), 255);
  EXPECT_EQ(mask.at<uint8_t>(240, 200), 0);
  Config config = MapTestConfig();
  StaticMapper masked(config);
  masked.OnKeyFrames({keyframe}, {});
  EXPECT_EQ(masked.stats().voxels, VoxelsOfSamples(kPlaneDepthM, false));  // the plane alone
  config.map.dynamic_masks = false;
  StaticMapper unmasked(config);
  unmasked.OnKeyFrames({keyframe}, {});
  EXPECT_EQ(unmasked.stats().voxels,
            VoxelsOfSamples(kPlaneDepthM, false) + VoxelsOfSamples(1.51, true));
}

TEST(StaticMapper, RejectsAnInvalidConfigNamingTheParameter) {
  const auto error_of = [](const Config& config) -> std::string {
    try {
      StaticMapper mapper(config);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "";
  };
  Config config = MapTestConfig();
  config.map.voxel_size_m = 0.0;
  EXPECT_NE(error_of(config).find("map.voxel_size_m"), std::string::npos);
  config = MapTestConfig();
  config.map.extent_m = 0.2;
  config.map.voxel_size_m = 0.5;
  EXPECT_NE(error_of(config).find("map.extent_m"), std::string::npos);
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
  try {
    WritePcd("/nonexistent/folder/map.pcd", cloud);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/folder/map.pcd"), std::string::npos);
  }
  EXPECT_THROW(ReadPcd("/nonexistent/folder/map.pcd"), std::runtime_error);
}

}  // namespace
}  // namespace dslam
