#include "dslam/static_points/segmentation.h"

#include <random>

#include <gtest/gtest.h>

namespace dslam {
namespace {

std::vector<Eigen::Vector3d> UnitCube() {
  std::vector<Eigen::Vector3d> points;
  for (int c = 0; c < 8; ++c) points.emplace_back(c & 1, (c >> 1) & 1, (c >> 2) & 1);
  return points;
}

TEST(ConnectedComponents, KnownGraph) {
  // 0-1-2 chain, 3-4 pair (edge 3-4 culled), 5-6 pair, 7 alone.
  const std::vector<GraphEdge> edges = {{0, 1}, {1, 2}, {3, 4}, {5, 6}, {2, 5}};
  const std::vector<bool> kept = {true, true, false, true, false};
  const auto c = ConnectedComponents(8, edges, kept);
  EXPECT_EQ(c, (std::vector<int>{0, 0, 0, 1, 2, 3, 3, 4}));
  const auto all = ConnectedComponents(8, edges, {});
  EXPECT_EQ(all, (std::vector<int>{0, 0, 0, 1, 1, 0, 0, 2}));
}

TEST(ConnectedComponents, LongChainNeedsNoRecursion) {
  const int n = 200000;
  std::vector<GraphEdge> edges;
  for (int i = n - 2; i >= 0; --i) edges.push_back({i, i + 1});
  const auto c = ConnectedComponents(n, edges, {});
  for (int id : c) ASSERT_EQ(id, 0);
}

TEST(ComponentCount, LargestIdPlusOne) {
  EXPECT_EQ(ComponentCount({}), 0);
  EXPECT_EQ(ComponentCount({0}), 1);
  EXPECT_EQ(ComponentCount({0, 0, 1, 0, 2}), 3);
  const std::vector<GraphEdge> edges = {{0, 1}, {1, 2}, {3, 4}, {5, 6}, {2, 5}};
  EXPECT_EQ(ComponentCount(ConnectedComponents(8, edges, {true, true, false, true, false})), 5);
}

TEST(ConvexHullVolume, UnitCubeAndDegenerateSets) {
  EXPECT_NEAR(ConvexHullVolume(UnitCube()), 1.0, 1e-12);
  auto cube = UnitCube();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 100; ++i) cube.emplace_back(u(rng), u(rng), u(rng));  // interior points
  EXPECT_NEAR(ConvexHullVolume(cube), 1.0, 1e-12);
  // Regular tetrahedron-ish corner: volume 1/6.
  EXPECT_NEAR(ConvexHullVolume({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), 1.0 / 6.0, 1e-12);
  EXPECT_EQ(ConvexHullVolume({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), 0.0);
  EXPECT_EQ(ConvexHullVolume({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {0.5, 0.2, 1}}), 0.0);
  EXPECT_EQ(ConvexHullVolume({{0, 0, 0}, {0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}), 0.0);
}

// Component 0: a large 2 m cube (8 corners + 4 inner points); component 1: a small dense box;
// point 28 alone.
std::vector<Eigen::Vector3d> TwoBoxes(std::vector<int>* component) {
  std::vector<Eigen::Vector3d> points;
  for (const auto& c : UnitCube()) points.push_back(2.0 * c);
  for (int i = 0; i < 4; ++i) points.emplace_back(0.5 + 0.2 * i, 1.0, 1.0);
  for (int i = 0; i < 16; ++i) points.emplace_back(5.0 + 0.1 * (i & 3), 0.2 * (i >> 2), i % 3);
  points.emplace_back(9, 9, 9);
  component->assign(12, 0);
  component->insert(component->end(), 16, 1);
  component->push_back(2);
  return points;
}

TEST(SelectStaticComponent, LargestVolumeWinsOverMostPoints) {
  std::vector<int> component;
  const auto points = TwoBoxes(&component);
  StaticSelectionOptions options;
  const StaticSelection s = SelectStaticComponent(points, component, options);
  EXPECT_EQ(s.static_component, 0);  // 8 m^3 with 12 points beats 16 points in < 0.4 m^3
  EXPECT_NEAR(s.component_volumes[0], 8.0, 1e-9);
  EXPECT_EQ(s.labels[0], PointLabel::kStatic);
  EXPECT_EQ(s.labels[12], PointLabel::kDynamic);
  EXPECT_EQ(s.labels[28], PointLabel::kIsolated);
}

TEST(SelectStaticComponent, TinyStaticComponentGivesNoDecision) {
  std::vector<int> component;
  const auto points = TwoBoxes(&component);
  StaticSelectionOptions options;
  options.min_static_points = 13;  // the largest-volume component has 12 points
  const StaticSelection s = SelectStaticComponent(points, component, options);
  EXPECT_EQ(s.static_component, -1);
  for (PointLabel l : s.labels) EXPECT_EQ(l, PointLabel::kUndecided);
}

// Two similar volumes (1 m^3 and 0.857 m^3): the larger is still chosen.
TEST(SelectStaticComponent, SimilarVolumesLargerWins) {
  std::vector<Eigen::Vector3d> points;
  std::vector<int> component;
  for (int box = 0; box < 2; ++box) {
    for (const auto& c : UnitCube()) {
      points.push_back(Eigen::Vector3d(3.0 * box, 0, 0) + c * (box == 0 ? 1.0 : 0.95));
      component.push_back(box);
    }
  }
  StaticSelectionOptions options;
  options.min_static_points = 8;
  const StaticSelection s = SelectStaticComponent(points, component, options);
  EXPECT_EQ(s.static_component, 0);
  EXPECT_EQ(s.labels[0], PointLabel::kStatic);
  EXPECT_EQ(s.labels[8], PointLabel::kDynamic);
}

}  // namespace
}  // namespace dslam
