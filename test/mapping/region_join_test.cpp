// JoinStackedRegions on hand-made masks: rectangles of cells with given world boxes.
#include "dslam/mapping/region_join.h"

#include <gtest/gtest.h>

namespace dslam {
namespace {

/// Adds a region over the cell rectangle `cells` with the world box [min, max] [m] and one point.
void AddRegion(const cv::Rect& cells, const Eigen::Vector3d& min_world,
               const Eigen::Vector3d& max_world, DynamicMask* mask) {
  DynamicRegion region;
  region.label = static_cast<uint16_t>(mask->regions.size() + 1);
  region.cells = cells.area();
  region.min_world = min_world;
  region.max_world = max_world;
  region.centroid_world = 0.5 * (min_world + max_world);
  region.points = {static_cast<PointId>(100 + region.label)};
  region.points_world = {region.centroid_world};
  region.point_cells = {cells.y * mask->labels.cols + cells.x};
  mask->labels(cells).setTo(region.label);
  mask->regions.push_back(region);
}

DynamicMask EmptyMask() {
  DynamicMask mask;
  mask.decimation = 4;
  mask.labels = cv::Mat(120, 160, CV_16UC1, cv::Scalar(0));
  return mask;
}

TEST(RegionJoin, PartsOneAboveTheOtherBecomeOneRegion) {
  DynamicMask mask = EmptyMask();
  // A torso (cells rows 20-59) and legs (rows 70-109) of one person at 2 m, 0.15 m apart in
  // height; a second person to the right.
  AddRegion(cv::Rect(40, 20, 20, 40), {-0.2, -0.8, 1.9}, {0.2, 0.1, 2.1}, &mask);
  AddRegion(cv::Rect(42, 70, 16, 40), {-0.15, 0.25, 1.9}, {0.15, 0.9, 2.1}, &mask);
  AddRegion(cv::Rect(100, 20, 20, 60), {1.0, -0.8, 1.9}, {1.4, 0.9, 2.1}, &mask);
  const int torso_cells = mask.regions[0].cells, legs_cells = mask.regions[1].cells;
  EXPECT_EQ(JoinStackedRegions(DynamicMaskConfig(), ObjectsConfig(), &mask), 1);
  ASSERT_EQ(mask.regions.size(), 2u);
  EXPECT_EQ(mask.regions[0].cells, torso_cells + legs_cells);
  EXPECT_EQ(mask.regions[0].points.size(), 2u);
  EXPECT_NEAR(mask.regions[0].max_world.y(), 0.9, 1e-12);
  EXPECT_EQ(mask.LabelAt(4 * 50, 4 * 80), 1);  // the legs' cells carry the torso's label
  EXPECT_EQ(mask.regions[1].label, 2);         // the second person relabelled
  EXPECT_EQ(mask.LabelAt(4 * 110, 4 * 50), 2);
  EXPECT_EQ(cv::countNonZero(mask.labels == 3), 0);
}

TEST(RegionJoin, PeopleSideBySideOrOneBehindTheOtherStayApart) {
  DynamicMask mask = EmptyMask();
  // Side by side, touching in the world: their columns do not overlap.
  AddRegion(cv::Rect(20, 20, 20, 80), {-0.6, -0.8, 1.9}, {-0.2, 0.9, 2.1}, &mask);
  AddRegion(cv::Rect(41, 20, 20, 80), {-0.2, -0.8, 1.9}, {0.2, 0.9, 2.1}, &mask);
  // One behind the other: columns overlap, 0.6 m apart in depth.
  AddRegion(cv::Rect(100, 20, 20, 40), {1.0, -0.8, 1.9}, {1.4, 0.1, 2.1}, &mask);
  AddRegion(cv::Rect(102, 60, 16, 40), {1.0, 0.2, 2.7}, {1.4, 0.9, 2.9}, &mask);
  EXPECT_EQ(JoinStackedRegions(DynamicMaskConfig(), ObjectsConfig(), &mask), 0);
  EXPECT_EQ(mask.regions.size(), 4u);
}

TEST(RegionJoin, StackedPartsFartherThanTheMarginStayApart) {
  DynamicMask mask = EmptyMask();
  DynamicMaskConfig config;
  AddRegion(cv::Rect(40, 20, 20, 40), {-0.2, -0.8, 1.9}, {0.2, 0.1, 2.1}, &mask);
  AddRegion(cv::Rect(42, 70, 16, 40), {-0.15, 0.1 + config.margin_m + 0.01, 1.9}, {0.15, 0.9, 2.1},
            &mask);
  EXPECT_EQ(JoinStackedRegions(config, ObjectsConfig(), &mask), 0);
}

}  // namespace
}  // namespace dslam
