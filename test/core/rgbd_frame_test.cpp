// RgbdFrame::Check: every structural problem of a frame named, with the sizes involved.
#include <limits>
#include <memory>

#include <gtest/gtest.h>

#include "dslam/core/rgbd_frame.h"

namespace dslam {
namespace {

RgbdFrame Frame(int width, int height) {
  RgbdFrame frame;
  frame.stamp_s = 1.0;
  frame.colour = cv::Mat(height, width, CV_8UC3, cv::Scalar(0, 0, 0));
  frame.depth_m = cv::Mat(height, width, CV_32FC1, cv::Scalar(0.0f));
  frame.camera = std::make_shared<PinholeCamera>(width, height, 525.0, 525.0, 319.5, 239.5);
  return frame;
}

TEST(RgbdFrame, ValidFrameHasNoProblem) { EXPECT_EQ(Frame(640, 480).Check(), ""); }

TEST(RgbdFrame, ColourAndDepthSizeMismatchIsNamed) {
  RgbdFrame frame = Frame(640, 480);
  frame.depth_m = cv::Mat(240, 320, CV_32FC1, cv::Scalar(1.0f));
  EXPECT_EQ(frame.Check(),
            "depth image 320x240 differs from the colour image 640x480 (depth must be registered "
            "to colour at the same size)");
}

TEST(RgbdFrame, CameraSizeMismatchIsNamed) {
  RgbdFrame frame = Frame(640, 480);
  frame.camera = std::make_shared<PinholeCamera>(320, 240, 262.5, 262.5, 159.5, 119.5);
  EXPECT_EQ(frame.Check(), "camera 320x240 differs from the colour image 640x480");
}

TEST(RgbdFrame, WrongTypesAndMissingPartsAreNamed) {
  RgbdFrame frame = Frame(64, 48);
  frame.depth_m = cv::Mat(48, 64, CV_16UC1, cv::Scalar(1000));
  EXPECT_EQ(frame.Check(), "depth image must be CV_32FC1 metres, got OpenCV type 2");
  frame = Frame(64, 48);
  frame.colour = cv::Mat(48, 64, CV_8UC4);
  EXPECT_EQ(frame.Check(),
            "colour image must be 8-bit BGR or grey (CV_8UC3 or CV_8UC1), got OpenCV type 24");
  frame = Frame(64, 48);
  frame.depth_m = cv::Mat();
  EXPECT_EQ(frame.Check(), "frame has no depth image");
  frame = Frame(64, 48);
  frame.camera.reset();
  EXPECT_EQ(frame.Check(), "frame has no camera model");
  frame = Frame(64, 48);
  frame.stamp_s = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(frame.Check(), "frame stamp is not finite");
}

TEST(RgbdFrame, PixelValuesAreNotChecked) {
  // Saturated colour and non-finite depth are valid frames: the odometry decides what they give.
  RgbdFrame frame = Frame(64, 48);
  frame.colour.setTo(cv::Scalar(255, 255, 255));
  frame.depth_m.setTo(cv::Scalar(std::numeric_limits<float>::quiet_NaN()));
  EXPECT_EQ(frame.Check(), "");
}

}  // namespace
}  // namespace dslam
