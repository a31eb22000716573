// WindowMarkedPoints and MatchByDescriptor: the descriptor search of relocalisation, on random
// descriptors (seeded) whose correspondences are known.
#include "dslam/tracking/relocalisation.h"

#include <algorithm>
#include <random>

#include <gtest/gtest.h>

namespace dslam {
namespace {

cv::Mat RandomDescriptor(std::mt19937* rng) {
  cv::Mat d(1, 32, CV_8UC1);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int i = 0; i < 32; ++i) d.at<uint8_t>(0, i) = static_cast<uint8_t>(byte(*rng));
  return d;
}

// `bits` bits of `d` flipped (the first ones of each byte in turn).
cv::Mat Flipped(const cv::Mat& d, int bits) {
  cv::Mat out = d.clone();
  for (int b = 0; b < bits; ++b) out.at<uint8_t>(0, b % 32) ^= static_cast<uint8_t>(1 << (b / 32));
  return out;
}

PointMeasurement SomeMeasurement() {
  PointMeasurement m;
  m.y_camera = Eigen::Vector3d(0.0, 0.0, 2.0);
  m.covariance = Eigen::Matrix3d::Identity() * 1e-4;
  return m;
}

TEST(WindowMarkedPoints, MarkedPointsOfTheWindowOnceInOrder) {
  Map map;
  MapPoint marked, unmarked;
  unmarked.marked = false;
  const PointId a = map.AddPoint(marked), b = map.AddPoint(unmarked), c = map.AddPoint(marked);
  const PointId outside = map.AddPoint(marked);  // in no keyframe
  KeyFrame first, second;
  first.points = {c, b};
  second.points = {a, c};
  map.AddKeyFrame(first, KeyFrameMapLimits::Newest(5));
  map.AddKeyFrame(second, KeyFrameMapLimits::Newest(5));
  EXPECT_EQ(WindowMarkedPoints(map), (std::vector<PointId>{c, a}));
  EXPECT_NE(outside, a);
}

TEST(MatchByDescriptor, FindsEachPointsFeatureWithoutAPose) {
  std::mt19937 rng(7);
  Map map;
  FrameFeatures features;
  std::vector<PointId> points;
  std::vector<int> feature_of_point;
  const int kFeatures = 60;
  for (int f = 0; f < kFeatures; ++f) {
    Feature feature;
    if (f % 10 != 3) feature.measurement = SomeMeasurement();  // every tenth has no depth
    features.features.push_back(feature);
    features.descriptors.push_back(RandomDescriptor(&rng));
  }
  // Points seen again with up to 20 of 256 bits changed, in shuffled order.
  std::vector<int> order(kFeatures);
  for (int f = 0; f < kFeatures; ++f) order[f] = f;
  std::shuffle(order.begin(), order.end(), rng);
  for (int f : order) {
    MapPoint point;
    point.descriptor = Flipped(features.descriptors.row(f), f % 21);
    points.push_back(map.AddPoint(point));
    feature_of_point.push_back(f);
  }
  MapPoint stranger;  // a descriptor no feature has
  stranger.descriptor = RandomDescriptor(&rng);
  points.push_back(map.AddPoint(stranger));

  const std::vector<PointMatch> matches =
      MatchByDescriptor(map, points, features, DescriptorMatchRules());
  ASSERT_EQ(matches.size(), static_cast<size_t>(kFeatures - kFeatures / 10));
  for (size_t k = 0; k < matches.size(); ++k) {
    if (k > 0) {
      EXPECT_LT(matches[k - 1].feature, matches[k].feature);
    }
    const auto at = std::find(points.begin(), points.end(), matches[k].id) - points.begin();
    ASSERT_LT(at, kFeatures) << "the stranger was matched";
    EXPECT_EQ(feature_of_point[at], matches[k].feature);
    EXPECT_TRUE(features.features[matches[k].feature].measurement.has_value());
  }
}

TEST(MatchByDescriptor, DistantDescriptorsAreNotMatched) {
  std::mt19937 rng(11);
  Map map;
  FrameFeatures features;
  Feature feature;
  feature.measurement = SomeMeasurement();
  features.features.push_back(feature);
  features.descriptors.push_back(RandomDescriptor(&rng));
  MapPoint point;
  point.descriptor = Flipped(features.descriptors.row(0), 70);  // 70 bits >= 64
  const PointId id = map.AddPoint(point);
  EXPECT_TRUE(MatchByDescriptor(map, {id}, features, DescriptorMatchRules()).empty());
  DescriptorMatchRules loose;
  loose.max_distance_bits = 80;
  EXPECT_EQ(MatchByDescriptor(map, {id}, features, loose).size(), 1u);
}

}  // namespace
}  // namespace dslam
