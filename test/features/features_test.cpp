#include "dslam/features/features.h"

#include <cmath>
#include <memory>
#include <random>

#include <gtest/gtest.h>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "support/textured_frame.h"

namespace dslam {
namespace {

TEST(Features, NearRequestedCountSpreadOverImage) {
  const RgbdFrame frame = test::TexturedFrame(test::TestCamera(), 1, 2.0);
  const FeaturesConfig config;
  const FrameFeatures ff = ExtractFeatures(frame, config, DepthNoiseConfig());
  EXPECT_GE(static_cast<int>(ff.features.size()), 950);
  EXPECT_LE(static_cast<int>(ff.features.size()), config.num_features);
  EXPECT_EQ(ff.descriptors.rows, static_cast<int>(ff.features.size()));
  EXPECT_EQ(ff.descriptors.cols, 32);
  int per_region[4][4] = {};
  std::vector<int> per_octave(config.num_levels, 0);
  for (const Feature& f : ff.features) {
    ++per_region[static_cast<int>(f.uv_raw.y() / 120)][static_cast<int>(f.uv_raw.x() / 160)];
    ASSERT_GE(f.octave, 0);
    ASSERT_LT(f.octave, config.num_levels);
    ++per_octave[f.octave];
  }
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) EXPECT_GE(per_region[r][c], 25) << "region " << r << "," << c;
  }
  for (int l = 0; l < config.num_levels; ++l) EXPECT_GT(per_octave[l], 0) << "octave " << l;
  EXPECT_DOUBLE_EQ(ff.octave_scale[2], 1.2 * 1.2);
}

TEST(Features, SameKeypointsWithOneOrSeveralThreads) {
  const RgbdFrame frame = test::TexturedFrame(test::TestCamera(), 2, 2.0);
  cv::Mat grey = frame.colour;
  if (grey.channels() == 3) cv::cvtColor(frame.colour, grey, cv::COLOR_BGR2GRAY);
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  const std::vector<cv::KeyPoint> one = DetectDistributedKeypoints(grey, FeaturesConfig());
  cv::setNumThreads(4);
  const std::vector<cv::KeyPoint> several = DetectDistributedKeypoints(grey, FeaturesConfig());
  cv::setNumThreads(threads);
  ASSERT_EQ(one.size(), several.size());
  for (size_t k = 0; k < one.size(); ++k) {
    EXPECT_EQ(one[k].pt, several[k].pt) << k;
    EXPECT_EQ(one[k].angle, several[k].angle) << k;
    EXPECT_EQ(one[k].octave, several[k].octave) << k;
  }
}

TEST(Features, WeakCellsUseFallbackThreshold) {
  // Low-contrast texture: at threshold 20 hardly any corners, the fallback (7) finds them.
  RgbdFrame frame = test::TexturedFrame(test::TestCamera(), 3, 2.0);
  frame.colour.convertTo(frame.colour, -1, 0.12, 100.0);
  FeaturesConfig strict;
  strict.fast_threshold_min = strict.fast_threshold;
  const int without = static_cast<int>(DetectDistributedKeypoints(frame.colour, strict).size());
  const int with =
      static_cast<int>(DetectDistributedKeypoints(frame.colour, FeaturesConfig()).size());
  EXPECT_LT(without, 500);
  EXPECT_GE(with, 900);
}

TEST(Features, DepthMeasurementsBackProject) {
  const PinholeCamera camera = test::TestCamera();
  const RgbdFrame frame = test::TexturedFrame(camera, 2, 1.5);  // slanted plane, see helper
  const FrameFeatures ff = ExtractFeatures(frame, FeaturesConfig(), DepthNoiseConfig());
  EXPECT_GT(ff.NumWithDepth(), 0.95 * ff.features.size());
  for (const Feature& f : ff.features) {
    if (!f.measurement) continue;
    const Eigen::Vector3d& y = f.measurement->y_camera;
    EXPECT_NEAR((camera.Project(y) - f.uv_ideal).norm(), 0.0, 1e-6);
    const float d = frame.depth_m.at<float>(cvRound(f.uv_raw.y()), cvRound(f.uv_raw.x()));
    EXPECT_NEAR(y.z(), d, 1e-4);  // linear depth: the symmetric mixture mean is the centre
  }
}

TEST(Features, UndistortionApplied) {
  Distortion dist;
  dist.k1 = 0.2;
  dist.k2 = -0.1;
  dist.p1 = 0.001;
  const auto camera = std::make_shared<PinholeCamera>(640, 480, 525.0, 525.0, 319.5, 239.5, dist);
  const RgbdFrame frame = test::TexturedFrame(*camera, 1, 2.0);
  const FrameFeatures ff = ExtractFeatures(frame, FeaturesConfig(), DepthNoiseConfig());
  ASSERT_FALSE(ff.features.empty());
  double max_shift = 0.0;
  for (const Feature& f : ff.features) {
    EXPECT_NEAR((camera->Distort(f.uv_ideal) - f.uv_raw).norm(), 0.0, 1e-3);
    max_shift = std::max(max_shift, (f.uv_ideal - f.uv_raw).norm());
  }
  EXPECT_GT(max_shift, 10.0);  // corners move by tens of pixels with k1 = 0.2
}

TEST(Features, IntensityCentroidPointsUpTheGradient) {
  for (const double angle_deg : {0.0, 30.0, 90.0, 200.0, 315.0}) {
    const double a = angle_deg * CV_PI / 180.0;
    cv::Mat ramp(64, 64, CV_8UC1);
    for (int y = 0; y < ramp.rows; ++y) {
      for (int x = 0; x < ramp.cols; ++x) {
        ramp.at<uchar>(y, x) = cv::saturate_cast<uchar>(
            128.0 + 3.0 * ((x - 32) * std::cos(a) + (y - 32) * std::sin(a)));
      }
    }
    const float centre = IntensityCentroidAngle(ramp, cv::Point2f(32, 32));
    EXPECT_NEAR(std::remainder(centre - angle_deg, 360.0), 0.0, 1.5) << angle_deg;
  }
  // At the border only the disc's inside part counts: on a flat image the centroid then lies
  // towards the image's inside.
  const cv::Mat flat(64, 64, CV_8UC1, cv::Scalar(100));
  EXPECT_NEAR(IntensityCentroidAngle(flat, cv::Point2f(3, 32)), 0.0, 1e-3);
  EXPECT_NEAR(IntensityCentroidAngle(flat, cv::Point2f(32, 60)), 270.0, 1e-3);
  EXPECT_THROW(IntensityCentroidAngle(cv::Mat(64, 64, CV_8UC3), cv::Point2f(32, 32)),
               std::invalid_argument);
}

// The intensity-centroid angle summed row by row over the disc of radius 15 (ORB's patch; the
// half width of row dy is floor(sqrt(15^2 - dy^2))), each row clipped to the image.
float ReferenceCentroidAngle(const cv::Mat& level, const cv::Point2f& pt) {
  constexpr int kRadius = 15;
  const int cx = cvRound(pt.x), cy = cvRound(pt.y);
  long m01 = 0, m10 = 0;
  for (int dy = -kRadius; dy <= kRadius; ++dy) {
    if (cy + dy < 0 || cy + dy >= level.rows) continue;
    const int half = static_cast<int>(std::sqrt(kRadius * kRadius - dy * dy));
    for (int dx = std::max(-half, -cx); dx <= std::min(half, level.cols - 1 - cx); ++dx) {
      const int value = level.at<uchar>(cy + dy, cx + dx);
      m10 += dx * value;
      m01 += dy * value;
    }
  }
  const float angle = static_cast<float>(
      std::atan2(static_cast<double>(m01), static_cast<double>(m10)) * 180.0 / CV_PI);
  return angle < 0.0f ? angle + 360.0f : angle;
}

TEST(Features, IntensityCentroidEqualsTheRowByRowSumsInsideAndAtTheBorder) {
  std::mt19937 rng(17);
  cv::Mat image(140, 180, CV_8UC1);
  cv::randu(image, 0, 256);
  cv::GaussianBlur(image, image, cv::Size(5, 5), 1.5);   // some structure, not only noise
  const cv::Mat roi = image(cv::Rect(13, 9, 150, 120));  // a view: step != cols
  std::uniform_real_distribution<float> u(-2.0f, 151.0f), v(-2.0f, 121.0f);
  for (int i = 0; i < 3000; ++i) {
    const cv::Point2f pt(u(rng), v(rng));
    ASSERT_EQ(IntensityCentroidAngle(roi, pt), ReferenceCentroidAngle(roi, pt))
        << pt.x << " " << pt.y;
  }
}

TEST(Features, DescriptorsFollowARotatedImage) {
  // rBRIEF is steered by the orientation: the features of an image turned by 90 degrees carry
  // nearly the same descriptors as the ones they came from.
  const RgbdFrame frame = test::TexturedFrame(test::TestCamera(), 5, 2.0);
  RgbdFrame turned = frame;
  cv::rotate(frame.colour, turned.colour, cv::ROTATE_90_CLOCKWISE);
  cv::rotate(frame.depth_m, turned.depth_m, cv::ROTATE_90_CLOCKWISE);
  turned.camera = std::make_shared<PinholeCamera>(480, 640, 525.0, 525.0, 239.5, 319.5);
  const FrameFeatures a = ExtractFeatures(frame, FeaturesConfig(), DepthNoiseConfig());
  const FrameFeatures b = ExtractFeatures(turned, FeaturesConfig(), DepthNoiseConfig());
  std::vector<int> distances;
  for (size_t i = 0; i < a.features.size(); ++i) {
    if (a.features[i].octave != 0) continue;
    // (x, y) -> (rows - 1 - y, x) under a clockwise quarter turn.
    const Eigen::Vector2d expected(frame.colour.rows - 1 - a.features[i].uv_raw.y(),
                                   a.features[i].uv_raw.x());
    for (size_t j = 0; j < b.features.size(); ++j) {
      if (b.features[j].octave == 0 && (b.features[j].uv_raw - expected).norm() < 0.5) {
        distances.push_back(cv::norm(a.descriptors.row(i), b.descriptors.row(j), cv::NORM_HAMMING));
      }
    }
  }
  ASSERT_GT(distances.size(), 100u);
  std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
  EXPECT_LT(distances[distances.size() / 2], 20);  // random pairs are ~128 of 256 bits apart
}

TEST(Features, RejectsInvalidFrame) {
  RgbdFrame frame = test::TexturedFrame(test::TestCamera(), 1, 2.0);
  frame.depth_m = cv::Mat();
  EXPECT_THROW(ExtractFeatures(frame, FeaturesConfig(), DepthNoiseConfig()), std::invalid_argument);
}

}  // namespace
}  // namespace dslam
