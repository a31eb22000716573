// The static map's voxel store and keyframe back-projection with known answers: a plane fused
// into voxels, carving by a view that sees through, cropping to the extent.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/mapping/coloured_cloud.h"
#include "dslam/mapping/static_mapper.h"
#include "dslam/mapping/voxel_map.h"
#include "mapping/mapping_scenes.h"

namespace dslam {
namespace {

using test::kPlaneDepthM;
using test::MakeKeyFrame;
using test::MapTestConfig;
using test::Wall;

// The 5 cm voxels the samples (pixels 2, 6, 10, ...) of a fronto-parallel plane at kPlaneDepthM
// fall into, computed from the pinhole model directly.
size_t PlaneVoxels() {
  std::set<std::tuple<int, int, int>> keys;
  for (int v = 2; v < 480; v += 4) {
    for (int u = 2; u < 640; u += 4) {
      const double x = (u - 320.25) * kPlaneDepthM / 505.0;
      const double y = (v - 240.25) * kPlaneDepthM / 505.0;
      keys.emplace(std::floor(x / 0.05), std::floor(y / 0.05), std::floor(kPlaneDepthM / 0.05));
    }
  }
  return keys.size();
}

TEST(KeyFrameCloud, PlaneBackProjectsOnePointPerVoxel) {
  const KeyFrameRecord keyframe = MakeKeyFrame(0, Wall(kPlaneDepthM));
  BackProjection options;
  options.voxel_size_m = 0.0;
  EXPECT_EQ(BackProjectKeyFrame(keyframe.frame, cv::Mat(), options).size(), 160u * 120u);
  options.voxel_size_m = 0.05;
  const ColouredCloud cloud = BackProjectKeyFrame(keyframe.frame, cv::Mat(), options);
  EXPECT_EQ(cloud.size(), PlaneVoxels());
  for (const ColouredPoint& point : cloud) {
    EXPECT_NEAR(point.p.z(), kPlaneDepthM, 1e-5);
    EXPECT_EQ(point.r, 30);  // BGR (10, 20, 30)
    EXPECT_EQ(point.g, 20);
    EXPECT_EQ(point.b, 10);
  }
  // Depth out of range and masked pixels are skipped.
  options.max_depth_m = 2.0;
  EXPECT_TRUE(BackProjectKeyFrame(keyframe.frame, cv::Mat(), options).empty());
  options.max_depth_m = 4.0;
  EXPECT_TRUE(
      BackProjectKeyFrame(keyframe.frame, cv::Mat(480, 640, CV_8UC1, cv::Scalar(255)), options)
          .empty());
}

TEST(StaticMapper, FusesAKnownPlane) {
  StaticMapper mapper(MapTestConfig());
  // A keyframe seen from a pose 1 m to the right: the plane lies at x + 1 in the world.
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  T_world_camera.translation() = Eigen::Vector3d(1.0, 0.0, 0.0);
  const KeyFrameRecord keyframe = MakeKeyFrame(0, Wall(kPlaneDepthM), T_world_camera);
  mapper.OnKeyFrames({keyframe}, {});  // left the window at once: fused for good
  const StaticMapStats stats = mapper.stats();
  EXPECT_EQ(stats.voxels, PlaneVoxels());
  EXPECT_EQ(stats.fused_keyframes, 1);
  EXPECT_EQ(stats.window_keyframes, 0);
  const ColouredCloud cloud = mapper.Cloud();
  ASSERT_EQ(cloud.size(), PlaneVoxels());
  float min_x = 1e9f, max_x = -1e9f;
  for (const ColouredPoint& point : cloud) {
    EXPECT_NEAR(point.p.z(), kPlaneDepthM, 1e-5);
    min_x = std::min(min_x, point.p.x());
    max_x = std::max(max_x, point.p.x());
  }
  // Samples span x in camera [-1.273, 1.263] m (pixels 2 .. 638); voxel means stay inside.
  EXPECT_GT(min_x, 1.0 - 1.273 - 1e-4);
  EXPECT_LT(max_x, 1.0 + 1.263 + 1e-4);
  // The same plane again from the same pose adds hits, not voxels.
  mapper.OnKeyFrames({MakeKeyFrame(1, Wall(kPlaneDepthM), T_world_camera)}, {});
  EXPECT_EQ(mapper.stats().voxels, PlaneVoxels());
}

TEST(VoxelMap, CarveRemovesWhatAViewSeesThroughAndKeepsWellSupportedVoxels) {
  VoxelMap map(0.05);
  const ColouredPoint once{Eigen::Vector3f(0.01f, 0.01f, 1.51f), 0, 0, 0};
  const ColouredPoint twice{Eigen::Vector3f(-0.21f, 0.01f, 1.51f), 0, 0, 0};
  map.Add(twice, 0);
  map.Add(twice, 0);  // the same keyframe: still one hit
  map.Add(twice, 1);  // a second keyframe: two hits
  map.Add(once, 2);
  ASSERT_EQ(map.size(), 2u);
  const KeyFrameRecord wall = MakeKeyFrame(3, Wall(3.0f));
  const DepthView view(wall.frame, Eigen::Isometry3d::Identity(), 4, 0.3);
  const FreeSpaceTolerance tolerance = FreeSpaceTolerance::From(MapTestConfig().map, 0.3, 4.0);
  // Only voxels last hit by the given keyframe or a later one vote (`twice`: 1, `once`: 2).
  EXPECT_EQ(map.Carve(view, tolerance, 3), 0u);
  ASSERT_EQ(map.size(), 2u);
  EXPECT_EQ(map.Carve(view, tolerance, 2), 1u);  // `once`: 1 miss >= 1 hit
  ASSERT_EQ(map.size(), 1u);
  EXPECT_NEAR(map.Points()[0].p.x(), -0.21f, 1e-6);
  EXPECT_EQ(map.Carve(view, tolerance, 1), 0u);  // `twice`: 1 miss < 2 hits
  EXPECT_EQ(map.Carve(view, tolerance, 1), 1u);  // `twice`: 2 misses >= 2 hits
  EXPECT_EQ(map.size(), 0u);
}

TEST(VoxelMap, CropKeepsTheCubeAroundTheCentre) {
  VoxelMap map(0.1);
  for (int i = -10; i <= 10; ++i) {
    map.Add({Eigen::Vector3f(i + 0.05f, 0.05f, 0.05f), 0, 0, 0}, 0);
    map.Add({Eigen::Vector3f(0.05f, 0.05f, i + 0.05f), 0, 0, 0}, 0);
  }
  ASSERT_EQ(map.size(), 41u);  // the two lines share the voxel at i = 0
  // Half-side 3.5 m around (0, 0, 0): x and z in [-3.5, 3.5] keep i = -3 .. 3 on each line.
  EXPECT_EQ(map.Crop(Eigen::Vector3f::Zero(), 3.5), 41u - 13u);
  EXPECT_EQ(map.size(), 13u);
}

// Carve visits only the voxels of the keyframes it votes for and Crop walks only when the box of
// the fused points leaves its cube: the same voxels, votes and counts as walking every voxel
// (`every`: a first Carve with the largest oldest_keyframe makes each later one walk them all).
TEST(VoxelMap, CarveAndCropGiveWhatAWalkOverEveryVoxelGives) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> lateral(-1.2f, 1.2f), depth(1.0f, 3.6f);
  VoxelMap recent(0.05), every(0.05);
  const FreeSpaceTolerance tolerance = FreeSpaceTolerance::From(MapTestConfig().map, 0.3, 4.0);
  size_t carved = 0, cropped = 0;
  for (int k = 0; k < 60; ++k) {
    Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
    T_world_camera.translation() = Eigen::Vector3d(0.05 * k, 0.0, 0.0);
    const Eigen::Vector3f origin = T_world_camera.translation().cast<float>();
    for (int i = 0; i < 400; ++i) {
      const ColouredPoint point{origin + Eigen::Vector3f(lateral(rng), lateral(rng), depth(rng)), 0,
                                0, 0};
      recent.Add(point, k);
      every.Add(point, k);
    }
    const KeyFrameRecord wall = MakeKeyFrame(k, Wall(2.0f + 0.03f * (k % 20)), T_world_camera);
    const DepthView view(wall.frame, T_world_camera, 4, 0.3);
    if (k == 0) every.Carve(view, tolerance, std::numeric_limits<int>::max());
    const size_t removed = recent.Carve(view, tolerance, k - 8);
    ASSERT_EQ(removed, every.Carve(view, tolerance, k - 8)) << k;
    carved += removed;
    // Crop around a centre that leaves old points behind now and then.
    const Eigen::Vector3f centre = origin + Eigen::Vector3f(0.0f, 0.0f, 2.0f);
    size_t outside = 0;
    for (const ColouredPoint& point : recent.Points()) {
      outside += (point.p - centre).cwiseAbs().maxCoeff() > 1.6f;
    }
    ASSERT_EQ(recent.Crop(centre, 1.6), outside) << k;
    ASSERT_EQ(every.Crop(centre, 1.6), outside) << k;
    cropped += outside;
    ASSERT_EQ(recent.size(), every.size()) << k;
  }
  EXPECT_GT(carved, 100u);  // both happened
  EXPECT_GT(cropped, 100u);
  const auto sorted = [](const ColouredCloud& cloud) {
    std::vector<std::tuple<float, float, float>> points;
    for (const ColouredPoint& p : cloud) points.emplace_back(p.p.x(), p.p.y(), p.p.z());
    std::sort(points.begin(), points.end());
    return points;
  };
  EXPECT_EQ(sorted(recent.Points()), sorted(every.Points()));
}

TEST(StaticMapper, ExtentBoundsTheMapAroundTheNewestFusedKeyframe) {
  Config config = MapTestConfig();
  config.map.extent_m = 5.0;
  StaticMapper mapper(config);
  mapper.OnKeyFrames({MakeKeyFrame(0, Wall(kPlaneDepthM))}, {});
  ASSERT_EQ(mapper.stats().voxels, PlaneVoxels());
  // 20 m along x: the first plane (x within 1.3 m of 0) lies outside the cube around x = 20.
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation().x() = 20.0;
  mapper.OnKeyFrames({MakeKeyFrame(1, Wall(kPlaneDepthM), far)}, {});
  const StaticMapStats stats = mapper.stats();
  EXPECT_EQ(stats.voxels, PlaneVoxels());
  EXPECT_EQ(stats.cropped_voxels, PlaneVoxels());
  for (const ColouredPoint& point : mapper.Cloud()) EXPECT_GT(point.p.x(), 15.0f);
}

}  // namespace
}  // namespace dslam
