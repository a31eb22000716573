#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "dslam/core/depth_conversion.h"

namespace dslam {
namespace {

TEST(DepthConversion, MillimetresToMetres) {
  cv::Mat mm(2, 2, CV_16UC1);
  mm.at<uint16_t>(0, 0) = 0;
  mm.at<uint16_t>(0, 1) = 1000;
  mm.at<uint16_t>(1, 0) = 2500;
  mm.at<uint16_t>(1, 1) = 65535;
  const cv::Mat m = DepthFromMillimetres(mm);
  ASSERT_EQ(m.type(), CV_32FC1);
  EXPECT_EQ(m.at<float>(0, 0), 0.0f);
  EXPECT_FLOAT_EQ(m.at<float>(0, 1), 1.0f);
  EXPECT_FLOAT_EQ(m.at<float>(1, 0), 2.5f);
  EXPECT_FLOAT_EQ(m.at<float>(1, 1), 65.535f);
}

TEST(DepthConversion, TumScale) {
  cv::Mat units(1, 1, CV_16UC1, cv::Scalar(5000 * 3 / 2));
  EXPECT_FLOAT_EQ(DepthFromScaledUint16(units, 5000.0).at<float>(0, 0), 1.5f);
}

// tum_to_bag converts the same way (test/python/test_bagtools.py), so the node given a bag sees
// the depths dslam_run_dataset reads from the PNG files, bit for bit.
TEST(DepthConversion, EveryValueIsAFloatMultiplyByTheInverseScale) {
  cv::Mat units(1, 65536, CV_16UC1);
  for (int i = 0; i < units.cols; ++i) units.at<uint16_t>(0, i) = static_cast<uint16_t>(i);
  for (const double scale : {5000.0, 1000.0}) {
    const cv::Mat metres = DepthFromScaledUint16(units, scale);
    const float inverse = static_cast<float>(1.0 / scale);
    int differing = 0;
    for (int i = 0; i < units.cols; ++i) {
      differing += metres.at<float>(0, i) != static_cast<float>(i) * inverse;
    }
    EXPECT_EQ(differing, 0) << scale;
  }
}

TEST(DepthConversion, MetresCleansInvalidValues) {
  cv::Mat m(1, 5, CV_32FC1);
  m.at<float>(0, 0) = std::numeric_limits<float>::quiet_NaN();
  m.at<float>(0, 1) = std::numeric_limits<float>::infinity();
  m.at<float>(0, 2) = -1.0f;
  m.at<float>(0, 3) = 0.0f;
  m.at<float>(0, 4) = 1.25f;
  const cv::Mat clean = DepthFromMetres(m);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(clean.at<float>(0, i), 0.0f) << i;
  EXPECT_FLOAT_EQ(clean.at<float>(0, 4), 1.25f);
  EXPECT_EQ(CountValidDepth(clean), 1);
  EXPECT_EQ(CountValidDepth(m), 1);  // uncleaned: NaN, inf, negative and 0 are not valid
}

TEST(DepthConversion, RejectsWrongEncodings) {
  EXPECT_THROW(DepthFromMillimetres(cv::Mat(2, 2, CV_32FC1)), std::invalid_argument);
  EXPECT_THROW(DepthFromMetres(cv::Mat(2, 2, CV_16UC1)), std::invalid_argument);
  EXPECT_THROW(DepthFromScaledUint16(cv::Mat(2, 2, CV_16UC1), 0.0), std::invalid_argument);
}

TEST(DepthConversion, PngRoundTrip) {
  cv::Mat units(3, 4, CV_16UC1, cv::Scalar(10000));
  const std::string path = testing::TempDir() + "/dslam_depth_test.png";
  ASSERT_TRUE(cv::imwrite(path, units));
  const cv::Mat m = ReadDepthPng(path, 5000.0);
  EXPECT_FLOAT_EQ(m.at<float>(2, 3), 2.0f);
  EXPECT_THROW(ReadDepthPng(path + ".missing", 5000.0), std::runtime_error);
}

}  // namespace
}  // namespace dslam
