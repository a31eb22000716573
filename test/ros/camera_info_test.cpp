// CameraFromInfo: K and D for raw images, P for rectified ones, and one named error per bad field.
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "dslam/ros/conversions.h"

namespace dslam {
namespace ros_layer {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// 640x480 calibration whose P (rectified) differs from K (raw), as after
/// cv::getOptimalNewCameraMatrix.
sensor_msgs::CameraInfo Info() {
  sensor_msgs::CameraInfo info;
  info.width = 640;
  info.height = 480;
  info.distortion_model = "plumb_bob";
  info.D = {0.1, -0.2, 0.001, -0.002, 0.05};
  info.K = {525.0, 0, 319.5, 0, 520.0, 239.5, 0, 0, 1};
  info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.P = {510.0, 0, 321.0, 0, 0, 508.0, 242.0, 0, 0, 0, 1, 0};
  return info;
}

sensor_msgs::Image Colour(uint32_t width = 640, uint32_t height = 480) {
  sensor_msgs::Image image;
  image.width = width;
  image.height = height;
  image.encoding = "bgr8";
  return image;
}

std::string ErrorOf(const sensor_msgs::CameraInfo& info,
                    ImageGeometry geometry = ImageGeometry::kRaw,
                    const sensor_msgs::Image& colour = Colour()) {
  try {
    CameraFromInfo(info, colour, geometry);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(CameraInfo, RawImagesUseKAndDistortion) {
  const auto camera = CameraFromInfo(Info(), Colour(), ImageGeometry::kRaw);
  EXPECT_DOUBLE_EQ(camera->fx(), 525.0);
  EXPECT_DOUBLE_EQ(camera->fy(), 520.0);
  EXPECT_DOUBLE_EQ(camera->cx(), 319.5);
  EXPECT_DOUBLE_EQ(camera->cy(), 239.5);
  EXPECT_DOUBLE_EQ(camera->distortion().p2, -0.002);
  EXPECT_DOUBLE_EQ(camera->distortion().k3, 0.05);
}

TEST(CameraInfo, RectifiedImagesUsePAndNoDistortion) {
  const auto camera = CameraFromInfo(Info(), Colour(), ImageGeometry::kRectified);
  EXPECT_DOUBLE_EQ(camera->fx(), 510.0);
  EXPECT_DOUBLE_EQ(camera->fy(), 508.0);
  EXPECT_DOUBLE_EQ(camera->cx(), 321.0);
  EXPECT_DOUBLE_EQ(camera->cy(), 242.0);
  EXPECT_TRUE(camera->distortion().IsZero());
}

TEST(CameraInfo, RightStereoProjectionIsRejected) {
  sensor_msgs::CameraInfo info = Info();
  info.P[3] = -38.25;  // -fx' * baseline
  EXPECT_EQ(ErrorOf(info, ImageGeometry::kRectified),
            "camera_info P[3] (Tx) is -38.25: the projection of a second stereo camera; use the "
            "reference (left) camera's");
  EXPECT_EQ(ErrorOf(info, ImageGeometry::kRaw), "");  // raw images do not use P
}

TEST(CameraInfo, RectifiedWithoutPIsNamed) {
  sensor_msgs::CameraInfo info = Info();
  info.P = {};
  EXPECT_EQ(ErrorOf(info, ImageGeometry::kRectified),
            "camera_info P[0] (fx') is 0 (not calibrated; must be positive)");
}

TEST(CameraInfo, SizeZeroOrOtherThanTheImageIsNamed) {
  sensor_msgs::CameraInfo info = Info();
  info.width = info.height = 0;
  EXPECT_EQ(ErrorOf(info), "camera_info size is 0x0 (not calibrated)");
  EXPECT_EQ(ErrorOf(Info(), ImageGeometry::kRaw, Colour(320, 240)),
            "camera_info size 640x480 differs from the colour image's 320x240");
}

TEST(CameraInfo, BinningAndRegionOfInterestAreRejected) {
  sensor_msgs::CameraInfo info = Info();
  info.binning_x = 2;
  EXPECT_EQ(ErrorOf(info),
            "camera_info binning_x, binning_y are 2, 0: binned images are not supported");
  info = Info();
  info.roi.x_offset = 10;
  info.roi.width = 320;
  info.roi.height = 240;
  EXPECT_EQ(ErrorOf(info),
            "camera_info roi (10, 0) 320x240: a region of interest is not supported");
  info.roi.x_offset = 0;
  info.roi.width = 640;
  info.roi.height = 480;
  EXPECT_EQ(ErrorOf(info), "");  // the full image
}

TEST(CameraInfo, BadFocalLengthsAndCentresAreNamed) {
  const struct {
    int index;
    double value;
    const char* message;
  } cases[] = {
      {0, kNaN, "camera_info K[0] (fx) is NaN"},
      {0, 0.0, "camera_info K[0] (fx) is 0 (not calibrated; must be positive)"},
      {4, kInf, "camera_info K[4] (fy) is infinite"},
      {4, -520.0, "camera_info K[4] (fy) is -520 (not calibrated; must be positive)"},
      {2, kNaN, "camera_info K[2] (cx) is NaN"},
      {2, 700.0, "camera_info K[2] (cx) is 700, outside the image width [0, 640]"},
      {5, -kInf, "camera_info K[5] (cy) is infinite"},
      {5, -1.0, "camera_info K[5] (cy) is -1, outside the image height [0, 480]"},
      {1, 0.5, "camera_info K[1] (skew) is 0.5: skewed pixel axes are not supported"},
  };
  for (const auto& c : cases) {
    sensor_msgs::CameraInfo info = Info();
    info.K[c.index] = c.value;
    EXPECT_EQ(ErrorOf(info), c.message);
  }
  sensor_msgs::CameraInfo info = Info();
  info.P[6] = kNaN;
  EXPECT_EQ(ErrorOf(info, ImageGeometry::kRectified), "camera_info P[6] (cy') is NaN");
}

TEST(CameraInfo, BadDistortionIsNamed) {
  sensor_msgs::CameraInfo info = Info();
  info.D[1] = kNaN;
  EXPECT_EQ(ErrorOf(info), "camera_info D[1] is NaN");
  EXPECT_EQ(ErrorOf(info, ImageGeometry::kRectified), "");  // rectified images ignore D
  info = Info();
  info.D.resize(4);
  EXPECT_EQ(ErrorOf(info), "camera_info D has 4 coefficients, plumb_bob needs 5");
  info = Info();
  info.distortion_model = "equidistant";
  info.D.resize(4);
  EXPECT_EQ(ErrorOf(info),
            "camera_info distortion_model 'equidistant' is not supported with a non-zero D "
            "(supported: plumb_bob, rational_polynomial with k4..k6 = 0)");
  info.D.assign(4, 0.0);  // zeros: no distortion whatever the model
  EXPECT_EQ(ErrorOf(info), "");
  info = Info();
  info.distortion_model = "rational_polynomial";
  info.D = {0.1, -0.2, 0, 0, 0.05, 0.01, 0, 0};
  EXPECT_EQ(ErrorOf(info),
            "camera_info D[5] (k4) is 0.01: rational_polynomial k4..k6 are not supported");
  info.D[5] = 0.0;
  EXPECT_DOUBLE_EQ(CameraFromInfo(info, Colour(), ImageGeometry::kRaw)->distortion().k3, 0.05);
}

TEST(CameraInfo, EmptyDistortionIsNone) {
  sensor_msgs::CameraInfo info = Info();
  info.D.clear();
  info.distortion_model = "";
  EXPECT_TRUE(CameraFromInfo(info, Colour(), ImageGeometry::kRaw)->distortion().IsZero());
  info.distortion_model = "plumb_bob";
  EXPECT_TRUE(CameraFromInfo(info, Colour(), ImageGeometry::kRaw)->distortion().IsZero());
}

}  // namespace
}  // namespace ros_layer
}  // namespace dslam
