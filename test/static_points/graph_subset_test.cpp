// SpatiallyEvenSubset, NearestGraphPoints and InheritedLabel (graph_subset.h).
#include "dslam/static_points/graph_subset.h"

#include <algorithm>
#include <random>

#include <gtest/gtest.h>

namespace dslam {
namespace {

TEST(GraphSubset, KeepsEverythingUpToTheCap) {
  const std::vector<Eigen::Vector2d> uv = {{1, 2}, {3, 4}, {5, 6}};
  EXPECT_EQ(SpatiallyEvenSubset(uv, 3), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(SpatiallyEvenSubset(uv, 10), (std::vector<int>{0, 1, 2}));
  EXPECT_TRUE(SpatiallyEvenSubset(uv, 0).empty());
}

TEST(GraphSubset, SpreadsOverTheImageNotIntoADenseCluster) {
  // 400 points in a dense 20 px cluster first (truncation would keep only them), then a 20 x 20
  // grid over 640 x 480 px: with a cap of 400 nearly every grid point is kept.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> cluster(300.0, 320.0);
  std::vector<Eigen::Vector2d> uv;
  for (int i = 0; i < 400; ++i) uv.emplace_back(cluster(rng), cluster(rng));
  for (int r = 0; r < 20; ++r) {
    for (int c = 0; c < 20; ++c) uv.emplace_back(16.0 + 32.0 * c, 12.0 + 24.0 * r);
  }
  const std::vector<int> chosen = SpatiallyEvenSubset(uv, 400);
  ASSERT_EQ(chosen.size(), 400u);
  EXPECT_TRUE(std::is_sorted(chosen.begin(), chosen.end()));
  const auto grid = std::count_if(chosen.begin(), chosen.end(), [](int i) { return i >= 400; });
  EXPECT_GE(grid, 360);
}

TEST(GraphSubset, OnePerCellFirst) {
  // Two clusters far apart, three points each; cap 2: the first of each cluster.
  const std::vector<Eigen::Vector2d> uv = {{0, 0},     {1, 0},     {0, 1},
                                           {600, 400}, {601, 400}, {600, 401}};
  EXPECT_EQ(SpatiallyEvenSubset(uv, 2), (std::vector<int>{0, 3}));
}

TEST(GraphSubset, NearestPointsAndInheritedLabels) {
  const std::vector<Eigen::Vector3d> graph = {{0, 0, 1}, {1, 0, 1}, {0, 2, 1}};
  const std::vector<Eigen::Vector3d> others = {{0.9, 0.1, 1}, {0.1, 1.9, 1}, {-1, -1, 1}};
  EXPECT_EQ(NearestGraphPoints(graph, others), (std::vector<int>{1, 2, 0}));
  EXPECT_EQ(NearestGraphPoints({}, others), (std::vector<int>{-1, -1, -1}));
  EXPECT_EQ(InheritedLabel(PointLabel::kStatic), PointLabel::kStatic);
  EXPECT_EQ(InheritedLabel(PointLabel::kDynamic), PointLabel::kDynamic);
  EXPECT_EQ(InheritedLabel(PointLabel::kIsolated), PointLabel::kUnverified);
  EXPECT_EQ(InheritedLabel(PointLabel::kUndecided), PointLabel::kUnverified);
}

}  // namespace
}  // namespace dslam
