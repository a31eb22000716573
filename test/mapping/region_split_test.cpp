// SplitRegions on hand-made depth images: two box-shaped movers that touch in the
// image at the same depth (one region of ComputeDynamicMask), their points given velocities
// through a history of earlier positions, with seeded noise.
#include "dslam/mapping/region_split.h"

#include <memory>
#include <random>

#include <gtest/gtest.h>

namespace dslam {
namespace {

constexpr int kWidth = 640, kHeight = 480;
constexpr double kDepthM = 2.0, kStampS = 1.0, kBaselineS = 0.2;

struct TwoMovers {
  RgbdFrame frame;
  std::vector<ObservedPoint> points;
  std::vector<int> mover;  ///< per point: 0 or 1
};

/// A wall at 4 m and two boxes at 2 m over pixel rectangles a and b, `n` unmarked points each,
/// inside points_a and points_b (empty: the whole box).
TwoMovers MakeTwoMovers(const cv::Rect& a, const cv::Rect& b, int n, uint32_t seed,
                        const cv::Rect& points_a = {}, const cv::Rect& points_b = {}) {
  TwoMovers scene;
  scene.frame.camera = std::make_shared<PinholeCamera>(kWidth, kHeight, 525, 525, 319.5, 239.5);
  scene.frame.depth_m = cv::Mat(kHeight, kWidth, CV_32FC1, cv::Scalar(4.0f));
  scene.frame.colour = cv::Mat(kHeight, kWidth, CV_8UC3, cv::Scalar(200, 200, 200));
  std::mt19937 rng(seed);
  for (int m = 0; m < 2; ++m) {
    scene.frame.depth_m(m == 0 ? a : b).setTo(static_cast<float>(kDepthM));
    const cv::Rect& given = m == 0 ? points_a : points_b;
    const cv::Rect& rect = given.empty() ? (m == 0 ? a : b) : given;
    std::uniform_int_distribution<int> u(rect.x + 2, rect.x + rect.width - 3);
    std::uniform_int_distribution<int> v(rect.y + 2, rect.y + rect.height - 3);
    for (int i = 0; i < n; ++i) {
      ObservedPoint p;
      p.id = static_cast<PointId>(scene.points.size());
      p.uv_raw = Eigen::Vector2d(u(rng), v(rng));
      p.is_static = false;
      scene.points.push_back(p);
      scene.mover.push_back(m);
    }
  }
  return scene;
}

/// The positions kBaselineS before kStampS of the mask's points when mover m moves at
/// velocity[m] [m/s], plus Gaussian noise of `sigma_m` [m].
std::deque<PointPositions> History(const DynamicMask& mask, const TwoMovers& scene,
                                   const Eigen::Vector3d velocity[2], double sigma_m) {
  std::mt19937 rng(17);
  std::normal_distribution<double> noise(0.0, sigma_m);
  PointPositions before;
  before.stamp_s = kStampS - kBaselineS;
  for (const DynamicRegion& region : mask.regions) {
    for (size_t i = 0; i < region.points.size(); ++i) {
      const Eigen::Vector3d n(noise(rng), noise(rng), noise(rng));
      before.by_id[region.points[i]] =
          region.points_world[i] - velocity[scene.mover[region.points[i]]] * kBaselineS + n;
    }
  }
  return {before};
}

TEST(RegionSplit, TwoMoversAtDifferentVelocitiesAreSplitAtTheirBorder) {
  const cv::Rect a(170, 100, 130, 300), b(300, 100, 130, 300);  // 0.5 m wide each at 2 m
  const TwoMovers scene = MakeTwoMovers(a, b, 25, 3);
  DynamicMask mask = ComputeDynamicMask(scene.frame, Eigen::Isometry3d::Identity(), scene.points,
                                        DynamicMaskConfig());
  ASSERT_EQ(mask.regions.size(), 1u);  // one cluster: the points meet at the border
  const Eigen::Vector3d velocity[2] = {{1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  const int splits =
      SplitRegions(scene.frame, Eigen::Isometry3d::Identity(), History(mask, scene, velocity, 0.01),
                   kStampS, {}, DynamicMaskConfig(), ObjectsConfig(), &mask);
  EXPECT_EQ(splits, 1);
  ASSERT_EQ(mask.regions.size(), 2u);
  const uint16_t label_a = mask.LabelAt(200, 250), label_b = mask.LabelAt(400, 250);
  ASSERT_NE(label_a, 0);
  ASSERT_NE(label_b, 0);
  EXPECT_NE(label_a, label_b);
  for (int m = 0; m < 2; ++m) {
    const cv::Rect& rect = m == 0 ? a : b;
    const DynamicRegion& region = mask.regions[(m == 0 ? label_a : label_b) - 1];
    // Each part's centroid is its box's centre and holds only its own mover's points.
    const Eigen::Vector3d centre = scene.frame.camera->BackProject(
        {rect.x + rect.width / 2.0 - 0.5, rect.y + rect.height / 2.0 - 0.5}, kDepthM);
    EXPECT_LT((region.centroid_world - centre).norm(), 0.05) << m;
    EXPECT_EQ(region.points.size(), 25u);
    for (PointId id : region.points) EXPECT_EQ(scene.mover[id], m);
  }
}

TEST(RegionSplit, MoversWhosePointsCrowdTheirBorderAreJudgedByTheirCells) {
  // Each mover's points lie within 0.23 m of the common border: their median positions are
  // closer than split_min_distance_m (0.4 m), the cells each region grows around them are not.
  const cv::Rect a(120, 100, 180, 300), b(300, 100, 180, 300);
  const TwoMovers scene =
      MakeTwoMovers(a, b, 25, 11, cv::Rect(240, 100, 60, 300), cv::Rect(300, 100, 60, 300));
  DynamicMask mask = ComputeDynamicMask(scene.frame, Eigen::Isometry3d::Identity(), scene.points,
                                        DynamicMaskConfig());
  ASSERT_EQ(mask.regions.size(), 1u);
  const Eigen::Vector3d velocity[2] = {{1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  EXPECT_EQ(
      SplitRegions(scene.frame, Eigen::Isometry3d::Identity(), History(mask, scene, velocity, 0.01),
                   kStampS, {}, DynamicMaskConfig(), ObjectsConfig(), &mask),
      1);
  ASSERT_EQ(mask.regions.size(), 2u);
  const uint16_t label_a = mask.LabelAt(200, 250), label_b = mask.LabelAt(400, 250);
  ASSERT_NE(label_a, 0);
  ASSERT_NE(label_b, 0);
  EXPECT_NE(label_a, label_b);
  for (int v = 110; v < 390; v += 20) {  // the parts meet at the boxes' border
    EXPECT_EQ(mask.LabelAt(290, v), label_a) << v;
    EXPECT_EQ(mask.LabelAt(310, v), label_b) << v;
  }
  for (const DynamicRegion& region : mask.regions) {
    EXPECT_EQ(region.points.size(), 25u);
    const int m = region.label == label_a ? 0 : 1;
    for (PointId id : region.points) EXPECT_EQ(scene.mover[id], m);
  }
}

TEST(RegionSplit, OneVelocityOrMoversAboveEachOtherStayOneRegion) {
  const Eigen::Vector3d same[2] = {{1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
  const Eigen::Vector3d different[2] = {{1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  const TwoMovers side = MakeTwoMovers({170, 100, 130, 300}, {300, 100, 130, 300}, 25, 5);
  // One body (top) and a leg under it moving unlike it: their horizontal ranges overlap.
  const TwoMovers stacked = MakeTwoMovers({250, 60, 130, 200}, {260, 260, 110, 160}, 25, 7);
  for (const auto& [scene, velocity] :
       {std::make_pair(&side, same), std::make_pair(&stacked, different)}) {
    DynamicMask mask = ComputeDynamicMask(scene->frame, Eigen::Isometry3d::Identity(),
                                          scene->points, DynamicMaskConfig());
    ASSERT_EQ(mask.regions.size(), 1u);
    EXPECT_EQ(SplitRegions(scene->frame, Eigen::Isometry3d::Identity(),
                           History(mask, *scene, velocity, 0.01), kStampS, {}, DynamicMaskConfig(),
                           ObjectsConfig(), &mask),
              0);
    EXPECT_EQ(mask.regions.size(), 1u);
  }
}

TEST(RegionSplit, VelocitiesSplitWhereTwoTracksOneAboveTheOtherDoNot) {
  const cv::Rect a(170, 100, 130, 300), b(300, 100, 130, 300);
  const TwoMovers scene = MakeTwoMovers(a, b, 25, 13);
  // Two predictions 0.76 m apart, one above the other in mover a: no side-by-side parts.
  const std::vector<Eigen::Vector3d> stacked = {
      scene.frame.camera->BackProject({234.5, 150.5}, kDepthM),
      scene.frame.camera->BackProject({234.5, 350.5}, kDepthM)};
  const Eigen::Vector3d velocity[2] = {{1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  DynamicMask mask = ComputeDynamicMask(scene.frame, Eigen::Isometry3d::Identity(), scene.points,
                                        DynamicMaskConfig());
  ASSERT_EQ(mask.regions.size(), 1u);
  EXPECT_EQ(
      SplitRegions(scene.frame, Eigen::Isometry3d::Identity(), History(mask, scene, velocity, 0.01),
                   kStampS, stacked, DynamicMaskConfig(), ObjectsConfig(), &mask),
      1);
  ASSERT_EQ(mask.regions.size(), 2u);
  EXPECT_NE(mask.LabelAt(200, 250), mask.LabelAt(400, 250));
  for (const DynamicRegion& region : mask.regions) {
    const int m = scene.mover[region.points.front()];
    for (PointId id : region.points) EXPECT_EQ(scene.mover[id], m);
  }
}

TEST(RegionSplit, TwoTrackPredictionsSplitMoversThatStopped) {
  const cv::Rect a(170, 100, 130, 300), b(300, 100, 130, 300);
  const TwoMovers scene = MakeTwoMovers(a, b, 25, 9);
  const Eigen::Vector3d still[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  const std::vector<Eigen::Vector3d> predicted = {
      scene.frame.camera->BackProject({234.5, 249.5}, kDepthM),
      scene.frame.camera->BackProject({364.5, 249.5}, kDepthM)};
  // One prediction only, or two of one mover, split nothing.
  const std::vector<Eigen::Vector3d> one = {predicted[0]};
  const std::vector<Eigen::Vector3d> close = {
      predicted[0], scene.frame.camera->BackProject({250.5, 249.5}, kDepthM)};
  for (const auto* given : {&one, &close, &predicted}) {
    DynamicMask mask = ComputeDynamicMask(scene.frame, Eigen::Isometry3d::Identity(), scene.points,
                                          DynamicMaskConfig());
    ASSERT_EQ(mask.regions.size(), 1u);
    const int splits =
        SplitRegions(scene.frame, Eigen::Isometry3d::Identity(), History(mask, scene, still, 0.01),
                     kStampS, *given, DynamicMaskConfig(), ObjectsConfig(), &mask);
    if (given != &predicted) {
      EXPECT_EQ(splits, 0);
      continue;
    }
    EXPECT_EQ(splits, 1);
    ASSERT_EQ(mask.regions.size(), 2u);
    for (const DynamicRegion& region : mask.regions) {
      const int m = scene.mover[region.points.front()];
      for (PointId id : region.points) EXPECT_EQ(scene.mover[id], m);
      EXPECT_LT((region.centroid_world - predicted[m]).norm(), 0.05) << m;
    }
  }
}

}  // namespace
}  // namespace dslam
