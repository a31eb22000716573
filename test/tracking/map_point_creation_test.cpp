// DynamicNeighbourhood and CreateMapPoints: new points among moving points start unmarked and
// inherit how long their neighbours were seen moving.
#include "dslam/tracking/map_point_creation.h"

#include <gtest/gtest.h>

namespace dslam {
namespace {

Feature At(double u, double v) {
  Feature f;
  f.uv_raw = f.uv_ideal = Eigen::Vector2d(u, v);
  return f;
}

// Tracked points (features 0..n-1, matched) and one new feature (index n) at (100, 100).
struct Scene {
  Map map;
  FrameFeatures features;
  std::vector<PointMatch> matches;

  void AddTracked(double u, double v, bool marked, int dynamic_frames) {
    MapPoint point;
    point.marked = marked;
    point.dynamic_frames = dynamic_frames;
    matches.push_back({map.AddPoint(point), static_cast<int>(features.features.size())});
    features.features.push_back(At(u, v));
  }
};

TEST(DynamicNeighbourhood, MedianDynamicFramesOfUnmarkedNeighbours) {
  Scene scene;
  scene.AddTracked(110, 100, false, 2);
  scene.AddTracked(90, 100, false, 9);
  scene.AddTracked(100, 110, false, 5);
  scene.AddTracked(100, 90, true, 0);
  scene.AddTracked(400, 400, false, 30);  // outside the radius
  scene.features.features.push_back(At(100, 100));
  const std::vector<int> inherited =
      DynamicNeighbourhood(scene.features, scene.matches, scene.map, 40.0);
  ASSERT_EQ(inherited.size(), 6u);
  EXPECT_EQ(inherited[5], 5);  // 3 unmarked (2, 5, 9) outnumber 1 marked
}

TEST(DynamicNeighbourhood, MostlyMarkedOrAloneIsNotDynamic) {
  Scene scene;
  scene.AddTracked(110, 100, false, 4);
  scene.AddTracked(90, 100, true, 0);
  scene.features.features.push_back(At(100, 100));
  scene.features.features.push_back(At(300, 300));  // no neighbour at all
  const std::vector<int> inherited =
      DynamicNeighbourhood(scene.features, scene.matches, scene.map, 40.0);
  EXPECT_EQ(inherited[2], -1);  // a tie is not "mostly unmarked"
  EXPECT_EQ(inherited[3], -1);
}

TEST(CreateMapPoints, UnmarkedPointsInheritDynamicFrames) {
  FrameFeatures features;
  for (int i = 0; i < 2; ++i) {
    Feature f = At(100 + 50 * i, 100);
    PointMeasurement m;
    m.y_camera = Eigen::Vector3d(0.1 * i, 0.0, 2.0);
    m.covariance = Eigen::Matrix3d::Identity() * 1e-4;
    f.measurement = m;
    features.features.push_back(f);
  }
  features.descriptors = cv::Mat::zeros(2, 32, CV_8UC1);
  Map map;
  const CreationContext context{Eigen::Isometry3d::Identity(), 7, true};
  const std::vector<PointId> ids =
      CreateMapPoints(features, {false, false}, {-1, 4}, context, TrackingConfig(), &map);
  ASSERT_EQ(ids.size(), 2u);
  for (PointId id : ids) {
    const MapPoint& p = *map.Find(id);
    if (p.created_feature == 0) {
      EXPECT_TRUE(p.marked);
      EXPECT_TRUE(p.candidate);
      EXPECT_EQ(p.dynamic_frames, 0);
    } else {
      EXPECT_FALSE(p.marked);
      EXPECT_FALSE(p.candidate);
      EXPECT_EQ(p.dynamic_frames, 4);
    }
    EXPECT_EQ(p.created_frame, 7);
  }
}

}  // namespace
}  // namespace dslam
