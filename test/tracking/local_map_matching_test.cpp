#include "dslam/tracking/local_map_matching.h"

#include <random>

#include <gtest/gtest.h>

namespace dslam {
namespace {

// One feature straight ahead (pixel (320, 240)) with depth 2 m and a random descriptor.
FrameFeatures OneFeature(std::mt19937* rng) {
  FrameFeatures frame;
  frame.octave_scale = {1.0, 1.2};
  Feature f;
  f.uv_raw = f.uv_ideal = Eigen::Vector2d(320.0, 240.0);
  PointMeasurement m;
  m.y_camera = Eigen::Vector3d(0.0, 0.0, 2.0);
  m.covariance = Eigen::Matrix3d::Identity() * 1e-4;
  f.measurement = m;
  frame.features.push_back(f);
  frame.descriptors = cv::Mat(1, 32, CV_8UC1);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int c = 0; c < 32; ++c) frame.descriptors.at<uchar>(0, c) = static_cast<uchar>(byte(*rng));
  return frame;
}

// A map point with the feature's descriptor at `p_world` (camera = world frame).
PointId AddPoint(Map* map, const FrameFeatures& frame, const Eigen::Vector3d& p_world,
                 bool marked) {
  MapPoint point;
  point.p_world = p_world;
  point.descriptor = frame.descriptors.row(0).clone();
  point.marked = marked;
  return map->AddPoint(point);
}

class LocalMapMatchingTest : public ::testing::Test {
 protected:
  std::mt19937 rng_{11};
  FrameFeatures frame_ = OneFeature(&rng_);
  PinholeCamera camera_{640, 480, 500.0, 500.0, 320.0, 240.0};
  Map map_;
};

TEST_F(LocalMapMatchingTest, MarkedPointsAreSearchedAroundTheirLastMeasurement) {
  // The map position is 0.06 m (15 px) from the feature; the last frame, 0.1 m to the left of
  // this one, measured the point at the feature's 3D position: (0.1, 0, 2) in its camera frame.
  const Eigen::Vector3d p_world(0.06, 0.0, 2.0);
  const PointId marked = AddPoint(&map_, frame_, p_world, true);
  const PointId unmeasured = AddPoint(&map_, frame_, p_world, true);
  FrameMeasurements last_frame;
  last_frame.T_camera_world = Eigen::Translation3d(0.1, 0.0, 0.0) * Eigen::Isometry3d::Identity();
  PointMeasurement measured;
  measured.y_camera = Eigen::Vector3d(0.1, 0.0, 2.0);
  measured.covariance = Eigen::Matrix3d::Identity() * 1e-4;
  last_frame.by_point.emplace(marked, measured);
  LocalMapSearch search;
  search.radius_px = 10.0;
  const ProjectedLocalMap from_map =
      ProjectLocalMap(map_, {marked}, frame_, camera_, Eigen::Isometry3d::Identity(), search);
  ASSERT_EQ(from_map.points.size(), 1u);
  EXPECT_NEAR(from_map.points[0].uv_ideal.x(), 335.0, 1e-9);
  search.last_frame = &last_frame;
  const ProjectedLocalMap followed = ProjectLocalMap(map_, {marked, unmeasured}, frame_, camera_,
                                                     Eigen::Isometry3d::Identity(), search);
  ASSERT_EQ(followed.points.size(), 2u);
  EXPECT_NEAR(followed.points[0].uv_ideal.x(), 320.0, 1e-9);
  EXPECT_NEAR(followed.points[1].uv_ideal.x(), 335.0, 1e-9);  // no measurement: map position
  std::vector<bool> taken(1, false);
  const std::vector<PointMatch> matches = MatchLocalMap(
      &map_, {unmeasured, marked}, frame_, camera_, Eigen::Isometry3d::Identity(), search, &taken);
  ASSERT_EQ(matches.size(), 1u);
  EXPECT_EQ(matches[0].id, marked);
}

TEST_F(LocalMapMatchingTest, OnlyMatchLocalMapCountsVisibility) {
  const PointId inside = AddPoint(&map_, frame_, Eigen::Vector3d(0.0, 0.0, 2.0), true);
  const PointId outside = AddPoint(&map_, frame_, Eigen::Vector3d(5.0, 0.0, 2.0), true);
  const PointId behind = AddPoint(&map_, frame_, Eigen::Vector3d(0.0, 0.0, 0.05), true);
  LocalMapSearch search;
  search.count_visible = true;
  const ProjectedLocalMap projected = ProjectLocalMap(
      map_, {inside, outside, behind}, frame_, camera_, Eigen::Isometry3d::Identity(), search);
  ASSERT_EQ(projected.ids, std::vector<PointId>{inside});
  EXPECT_EQ(map_.Find(inside)->times_visible, 0);
  std::vector<bool> taken(1, false);
  MatchLocalMap(&map_, {inside, outside, behind}, frame_, camera_, Eigen::Isometry3d::Identity(),
                search, &taken);
  EXPECT_EQ(map_.Find(inside)->times_visible, 1);
  EXPECT_EQ(map_.Find(outside)->times_visible, 0);
  EXPECT_EQ(map_.Find(behind)->times_visible, 0);
  // A taken feature is not matched again.
  EXPECT_TRUE(ClaimLocalMapMatches(projected, frame_, &taken).empty());
}

}  // namespace
}  // namespace dslam
