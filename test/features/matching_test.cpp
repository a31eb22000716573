#include "dslam/features/matching.h"

#include <algorithm>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "support/textured_frame.h"

namespace dslam {
namespace {

cv::Mat RandomDescriptors(int rows, std::mt19937* rng) {
  std::uniform_int_distribution<int> byte(0, 255);
  cv::Mat d(rows, 32, CV_8UC1);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < 32; ++c) d.at<uchar>(r, c) = static_cast<uchar>(byte(*rng));
  }
  return d;
}

cv::Mat FlipBits(const cv::Mat& row, int bits) {
  cv::Mat out = row.clone();
  for (int b = 0; b < bits; ++b) out.at<uchar>(0, (b * 7) % 32) ^= static_cast<uchar>(1 << (b % 8));
  return out;
}

FrameFeatures GridFrame(std::mt19937* rng) {
  FrameFeatures frame;
  frame.octave_scale = {1.0, 1.2, 1.44};
  for (int i = 0; i < 50; ++i) {
    Feature f;
    f.uv_raw = f.uv_ideal = Eigen::Vector2d(20.0 + 40.0 * (i % 10), 20.0 + 40.0 * (i / 10));
    f.octave = i % 3;
    frame.features.push_back(f);
  }
  frame.descriptors = RandomDescriptors(50, rng);
  return frame;
}

TEST(Matching, HammingDistance) {
  const cv::Mat zeros = cv::Mat::zeros(1, 32, CV_8UC1);
  const cv::Mat ones(1, 32, CV_8UC1, cv::Scalar(255));
  EXPECT_EQ(HammingDistance(zeros, ones), 256);
  EXPECT_EQ(HammingDistance(zeros, FlipBits(zeros, 5)), 5);
  EXPECT_THROW(HammingDistance(zeros, cv::Mat::zeros(1, 16, CV_8UC1)), std::invalid_argument);
}

TEST(Matching, SearchByProjectionFindsKnownCorrespondences) {
  std::mt19937 rng(3);
  const FrameFeatures frame = GridFrame(&rng);
  std::vector<ProjectedPoint> points;
  for (int i = 0; i < 50; ++i) {
    ProjectedPoint p;
    p.uv_ideal = frame.features[i].uv_ideal + Eigen::Vector2d(3.0, -2.0);
    p.descriptor = FlipBits(frame.descriptors.row(i), 10);
    p.predicted_octave = (i % 2 == 0) ? frame.features[i].octave : -1;
    points.push_back(p);
  }
  const std::vector<int> match = SearchByProjection(points, frame);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(match[i], i);
  // Outside the radius (7 px at octave 0): no match even with an identical descriptor.
  points[0].uv_ideal = frame.features[0].uv_ideal + Eigen::Vector2d(8.0, 0.0);
  points[0].predicted_octave = 0;
  EXPECT_EQ(SearchByProjection(points, frame)[0], -1);
  // Radius scales with the predicted octave: 7 * 1.44 > 8 px (octave 1..3 allowed, feature 0 is 0).
  points[0].predicted_octave = 1;
  EXPECT_EQ(SearchByProjection(points, frame)[0], 0);
}

TEST(Matching, PerPointRadiusOverridesTheOptions) {
  std::mt19937 rng(5);
  const FrameFeatures frame = GridFrame(&rng);
  ProjectedPoint p;
  p.uv_ideal = frame.features[0].uv_ideal + Eigen::Vector2d(12.0, 0.0);
  p.descriptor = frame.descriptors.row(0).clone();
  p.predicted_octave = 0;
  EXPECT_EQ(SearchByProjection({p}, frame)[0], -1);  // 12 px > the options' 7 px
  p.radius_px = 12.5;
  EXPECT_EQ(SearchByProjection({p}, frame)[0], 0);
  p.radius_px = 11.5;
  EXPECT_EQ(SearchByProjection({p}, frame)[0], -1);
  // At octave 1 the point's radius is scaled like the options' one: 11.5 * 1.2 > 12 px.
  p.predicted_octave = 1;
  EXPECT_EQ(SearchByProjection({p}, frame)[0], 0);
}

TEST(Matching, RatioTestAndUniqueness) {
  std::mt19937 rng(4);
  FrameFeatures frame = GridFrame(&rng);
  // Feature 1 moved next to feature 0 with a near-identical descriptor: ambiguous.
  frame.features[1].uv_ideal = frame.features[0].uv_ideal + Eigen::Vector2d(2.0, 0.0);
  frame.descriptors.row(0).copyTo(frame.descriptors.row(1));
  ProjectedPoint p;
  p.uv_ideal = frame.features[0].uv_ideal;
  p.descriptor = frame.descriptors.row(0).clone();
  EXPECT_EQ(SearchByProjection({p}, frame)[0], -1);
  // Two points claiming feature 5: the closer descriptor keeps it.
  ProjectedPoint a, b;
  a.uv_ideal = b.uv_ideal = frame.features[5].uv_ideal;
  a.descriptor = FlipBits(frame.descriptors.row(5), 20);
  b.descriptor = FlipBits(frame.descriptors.row(5), 4);
  const std::vector<int> match = SearchByProjection({a, b}, frame);
  EXPECT_EQ(match[0], -1);
  EXPECT_EQ(match[1], 5);
}

TEST(Matching, ExtractedFeaturesMatchAcrossAShift) {
  const PinholeCamera camera = test::TestCamera();
  const RgbdFrame first = test::TexturedFrame(camera, 1, 2.0);
  RgbdFrame second = first;
  second.colour = cv::Mat();  // the copy shares pixels with `first`: warp into a new image
  const cv::Mat shift = (cv::Mat_<double>(2, 3) << 1, 0, 6, 0, 1, 4);
  cv::warpAffine(first.colour, second.colour, shift, first.colour.size(), cv::INTER_NEAREST,
                 cv::BORDER_REFLECT);
  const FrameFeatures a = ExtractFeatures(first, FeaturesConfig(), DepthNoiseConfig());
  const FrameFeatures b = ExtractFeatures(second, FeaturesConfig(), DepthNoiseConfig());
  std::vector<ProjectedPoint> points;
  for (size_t i = 0; i < a.features.size(); ++i) {
    points.push_back({a.features[i].uv_ideal + Eigen::Vector2d(6.0, 4.0), a.descriptors.row(i),
                      a.features[i].octave});
  }
  const std::vector<int> match = SearchByProjection(points, b);
  int matched = 0, correct = 0;
  for (size_t i = 0; i < match.size(); ++i) {
    if (match[i] < 0) continue;
    ++matched;
    const double tolerance = 1.5 * b.octave_scale[points[i].predicted_octave];  // level quantum
    correct += (b.features[match[i]].uv_ideal - points[i].uv_ideal).norm() < tolerance;
  }
  EXPECT_GT(matched, 0.5 * a.features.size());
  EXPECT_GT(correct, 0.95 * matched) << correct << " of " << matched;
}

TEST(Matching, BruteForceRecoversPermutation) {
  std::mt19937 rng(5);
  const cv::Mat train = RandomDescriptors(200, &rng);
  std::vector<int> perm(200);
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  cv::Mat query(100, 32, CV_8UC1);
  for (int q = 0; q < 100; ++q) FlipBits(train.row(perm[q]), 15).copyTo(query.row(q));
  const std::vector<DescriptorMatch> matches = MatchBruteForce(query, train);
  ASSERT_EQ(matches.size(), 100u);
  for (const DescriptorMatch& m : matches) {
    EXPECT_EQ(m.train, perm[m.query]);
    EXPECT_EQ(m.distance, 15);
  }
  // A query equidistant to two identical train rows fails the ratio test.
  cv::Mat twin(2, 32, CV_8UC1);
  train.row(0).copyTo(twin.row(0));
  train.row(0).copyTo(twin.row(1));
  EXPECT_TRUE(MatchBruteForce(train.row(0), twin).empty());
}

}  // namespace
}  // namespace dslam
