#include "dslam/features/features.h"

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

TEST(Features, RejectsInvalidFrame) {
  RgbdFrame frame = test::TexturedFrame(test::TestCamera(), 1, 2.0);
  frame.depth_m = cv::Mat();
  EXPECT_THROW(ExtractFeatures(frame, FeaturesConfig(), DepthNoiseConfig()), std::invalid_argument);
}

}  // namespace
}  // namespace dslam
