// ComputeDynamicMask on hand-made depth images: a wall with one or two box-shaped movers in
// front of it and a floor, seeded by unmarked points whose pixels are drawn with a seeded RNG.
#include "dslam/mapping/dynamic_mask.h"

#include <memory>
#include <random>

#include <gtest/gtest.h>

namespace dslam {
namespace {

constexpr int kWidth = 640, kHeight = 480;

/// A frame seeing a wall at 4 m; boxes (pixel rectangles at their own depth) in front of it.
struct Scene {
  RgbdFrame frame;
  std::vector<cv::Rect> boxes;
  std::vector<float> box_depths;
};

Scene MakeScene(const std::vector<cv::Rect>& boxes, const std::vector<float>& depths) {
  Scene scene;
  scene.frame.camera = std::make_shared<PinholeCamera>(kWidth, kHeight, 525, 525, 319.5, 239.5);
  scene.frame.depth_m = cv::Mat(kHeight, kWidth, CV_32FC1, cv::Scalar(4.0f));
  scene.frame.colour = cv::Mat(kHeight, kWidth, CV_8UC3, cv::Scalar(200, 200, 200));
  for (size_t i = 0; i < boxes.size(); ++i) {
    scene.frame.depth_m(boxes[i]).setTo(depths[i]);
    scene.frame.colour(boxes[i]).setTo(cv::Scalar(0, 0, 255));
  }
  scene.boxes = boxes;
  scene.box_depths = depths;
  return scene;
}

/// `n` points at random pixels of `rect`, labelled `is_static`.
void AddPoints(const cv::Rect& rect, int n, bool is_static, std::mt19937* rng,
               std::vector<ObservedPoint>* points) {
  std::uniform_int_distribution<int> u(rect.x, rect.x + rect.width - 1);
  std::uniform_int_distribution<int> v(rect.y, rect.y + rect.height - 1);
  for (int i = 0; i < n; ++i) {
    ObservedPoint p;
    p.id = static_cast<PointId>(points->size());
    p.uv_raw = Eigen::Vector2d(u(*rng), v(*rng));
    p.is_static = is_static;
    points->push_back(p);
  }
}

/// Share of the pixels (cell centres) of `rect` that carry a non-zero label.
double Recall(const DynamicMask& mask, const cv::Rect& rect) {
  int inside = 0, hit = 0;
  for (int v = rect.y; v < rect.y + rect.height; v += mask.decimation) {
    for (int u = rect.x; u < rect.x + rect.width; u += mask.decimation) {
      ++inside;
      hit += mask.LabelAt(u, v) != 0;
    }
  }
  return static_cast<double>(hit) / inside;
}

TEST(DynamicMask, MaskCoversTheMoverAndNothingOfTheWall) {
  const cv::Rect person(200, 100, 120, 300);
  Scene scene = MakeScene({person}, {2.0f});
  std::mt19937 rng(7);
  std::vector<ObservedPoint> points;
  AddPoints(person, 15, false, &rng, &points);
  AddPoints(cv::Rect(400, 50, 200, 400), 40, true, &rng, &points);
  const DynamicMask mask =
      ComputeDynamicMask(scene.frame, Eigen::Isometry3d::Identity(), points, DynamicMaskConfig());
  ASSERT_EQ(mask.regions.size(), 1u);
  EXPECT_GT(Recall(mask, person), 0.97);
  const int person_cells = (person.width / 4) * (person.height / 4);
  EXPECT_LE(mask.regions[0].cells, person_cells + 2 * (person.width + person.height) / 4);
  // The region's centroid is the box's: depth 2 m, centred at pixel (259.5, 249.5).
  const Eigen::Vector3d expected = scene.frame.camera->BackProject({259.5, 249.5}, 2.0);
  EXPECT_LT((mask.regions[0].centroid_world - expected).norm(), 0.03);
  EXPECT_NEAR(mask.regions[0].max_world.y() - mask.regions[0].min_world.y(),
              person.height * 2.0 / 525.0, 0.03);
  EXPECT_NEAR(mask.regions[0].mean_colour.z(), 1.0, 1e-9);  // red (B, G, R)
}

TEST(DynamicMask, TwoMoversGiveTwoRegionsAndTheWorldPoseMovesTheirCentroids) {
  const cv::Rect a(50, 100, 80, 200), b(450, 150, 100, 250);
  Scene scene = MakeScene({a, b}, {1.5f, 2.5f});
  std::mt19937 rng(11);
  std::vector<ObservedPoint> points;
  AddPoints(a, 10, false, &rng, &points);
  AddPoints(b, 15, false, &rng, &points);
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  T_world_camera.translation() = Eigen::Vector3d(1.0, -2.0, 0.5);
  const DynamicMask mask =
      ComputeDynamicMask(scene.frame, T_world_camera, points, DynamicMaskConfig());
  ASSERT_EQ(mask.regions.size(), 2u);
  EXPECT_GT(Recall(mask, a), 0.97);
  EXPECT_GT(Recall(mask, b), 0.97);
  EXPECT_NE(mask.LabelAt(90, 200), mask.LabelAt(500, 300));
  for (const DynamicRegion& region : mask.regions) {
    const double z = region.centroid_world.z() - 0.5;
    EXPECT_TRUE(std::abs(z - 1.5) < 0.01 || std::abs(z - 2.5) < 0.01) << z;
  }
}

TEST(DynamicMask, FewOrNoUnmarkedPointsGiveNoMask) {
  const cv::Rect person(200, 100, 120, 300);
  Scene scene = MakeScene({person}, {2.0f});
  std::mt19937 rng(3);
  std::vector<ObservedPoint> points;
  AddPoints(person, DynamicMaskConfig().min_cluster_points - 1, false, &rng, &points);
  const DynamicMask mask =
      ComputeDynamicMask(scene.frame, Eigen::Isometry3d::Identity(), points, DynamicMaskConfig());
  EXPECT_TRUE(mask.regions.empty());
  EXPECT_EQ(mask.MaskedShare(), 0.0);
}

TEST(DynamicMask, GrowthIntoATouchingFloorStopsAtTheMargin) {
  // A floor 0.9 m below the optical axis: depth z = 0.9 fy / (v - cy) below the horizon. A
  // mover stands on it at 3 m: its feet touch the floor, whose depth is continuous there.
  Scene scene = MakeScene({}, {});
  for (int v = 240; v < kHeight; ++v) {
    const float z = std::min(4.0f, static_cast<float>(0.9 * 525.0 / (v - 239.5)));
    scene.frame.depth_m.row(v).setTo(z);
  }
  const int feet_v = static_cast<int>(239.5 + 0.9 * 525.0 / 3.0);  // floor row at 3 m
  const cv::Rect person(280, feet_v - 250, 80, 250);
  scene.frame.depth_m(person).setTo(3.0f);
  std::mt19937 rng(5);
  std::vector<ObservedPoint> points;
  AddPoints(person, 20, false, &rng, &points);
  DynamicMaskConfig config;
  const DynamicMask mask =
      ComputeDynamicMask(scene.frame, Eigen::Isometry3d::Identity(), points, config);
  ASSERT_EQ(mask.regions.size(), 1u);
  EXPECT_GT(Recall(mask, person), 0.95);
  // No floor cell farther than the margin from the person's box is masked.
  for (int v = feet_v + 4; v < kHeight; v += 4) {
    for (int u = 2; u < kWidth; u += 4) {
      if (mask.LabelAt(u, v) == 0) continue;
      const Eigen::Vector3d p = scene.frame.camera->BackProject(
          {u / 4 * 4 + 2.0, v / 4 * 4 + 2.0},
          scene.frame.depth_m.at<float>(v / 4 * 4 + 2, u / 4 * 4 + 2));
      EXPECT_LT(p.z(), 3.0 + config.margin_m + 1e-6);
      EXPECT_GT(p.z(), 3.0 - config.margin_m - 1e-6);
    }
  }
}

TEST(DynamicMask, SmallClustersAreKeptNearAPredictedObjectOnly) {
  // Two movers with 2 unmarked points each (below min_cluster_points); one of them is where a
  // tracked object is expected.
  const cv::Rect a(80, 180, 60, 80), b(480, 180, 60, 80);  // 0.23 x 0.3 m: one cluster each
  Scene scene = MakeScene({a, b}, {2.0f, 2.0f});
  std::mt19937 rng(13);
  std::vector<ObservedPoint> points;
  AddPoints(a, 2, false, &rng, &points);
  AddPoints(b, 2, false, &rng, &points);
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  T_world_camera.translation() = Eigen::Vector3d(0.5, 0.0, 1.0);
  const Eigen::Vector3d near_a =
      T_world_camera * scene.frame.camera->BackProject({109.5, 219.5}, 2.0);
  EXPECT_TRUE(
      ComputeDynamicMask(scene.frame, T_world_camera, points, DynamicMaskConfig()).regions.empty());
  const DynamicMask mask = ComputeDynamicMask(scene.frame, T_world_camera, points,
                                              DynamicMaskConfig(), {near_a}, 0.6, 2);
  ASSERT_EQ(mask.regions.size(), 1u);
  EXPECT_GT(Recall(mask, a), 0.97);
  EXPECT_EQ(Recall(mask, b), 0.0);
  // Three points needed: none kept.
  EXPECT_TRUE(
      ComputeDynamicMask(scene.frame, T_world_camera, points, DynamicMaskConfig(), {near_a}, 0.6, 3)
          .regions.empty());
}

}  // namespace
}  // namespace dslam
