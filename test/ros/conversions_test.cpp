#include "dslam/ros/conversions.h"

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>
#include <sensor_msgs/image_encodings.h>

namespace dslam {
namespace ros_layer {
namespace {

sensor_msgs::Image MakeImage(int w, int h, const std::string& encoding, int bytes_per_pixel) {
  sensor_msgs::Image image;
  image.width = w;
  image.height = h;
  image.encoding = encoding;
  image.step = w * bytes_per_pixel;
  image.data.assign(image.step * h, 0);
  return image;
}

TEST(Conversions, NormaliseFrameIdStripsLeadingSlashes) {
  EXPECT_EQ(NormaliseFrameId("/openni_rgb_optical_frame"), "openni_rgb_optical_frame");
  EXPECT_EQ(NormaliseFrameId("//a/b"), "a/b");
  EXPECT_EQ(NormaliseFrameId("camera"), "camera");
  EXPECT_EQ(NormaliseFrameId("/"), "");
}

TEST(Conversions, DepthMillimetresAndMetres) {
  sensor_msgs::Image mm = MakeImage(2, 1, "16UC1", 2);
  const uint16_t values[2] = {1500, 0};
  std::memcpy(mm.data.data(), values, sizeof(values));
  const cv::Mat a = DepthFromImage(mm);
  EXPECT_FLOAT_EQ(a.at<float>(0, 0), 1.5f);
  EXPECT_FLOAT_EQ(a.at<float>(0, 1), 0.0f);

  sensor_msgs::Image m = MakeImage(3, 1, "32FC1", 4);
  const float f[3] = {2.25f, std::numeric_limits<float>::quiet_NaN(), -1.0f};
  std::memcpy(m.data.data(), f, sizeof(f));
  const cv::Mat b = DepthFromImage(m);
  EXPECT_FLOAT_EQ(b.at<float>(0, 0), 2.25f);
  EXPECT_FLOAT_EQ(b.at<float>(0, 1), 0.0f);
  EXPECT_FLOAT_EQ(b.at<float>(0, 2), 0.0f);

  EXPECT_THROW(DepthFromImage(MakeImage(2, 2, "rgb8", 3)), std::invalid_argument);
}

TEST(Conversions, ColourRgbBecomesBgrAndBadEncodingsThrow) {
  sensor_msgs::Image rgb = MakeImage(1, 1, "rgb8", 3);
  rgb.data = {10, 20, 30};
  const cv::Mat bgr = ColourFromImage(rgb);
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 0), cv::Vec3b(30, 20, 10));
  EXPECT_EQ(ColourFromImage(MakeImage(4, 3, "mono8", 1)).type(), CV_8UC1);
  EXPECT_THROW(ColourFromImage(MakeImage(1, 1, "16UC1", 2)), std::invalid_argument);
}

TEST(Conversions, CameraFromInfo) {
  sensor_msgs::CameraInfo info;
  info.width = 640;
  info.height = 480;
  info.K = {525.0, 0, 319.5, 0, 520.0, 239.5, 0, 0, 1};
  info.distortion_model = "plumb_bob";
  info.D = {0.1, -0.2, 0.0, 0.0, 0.05};
  const auto camera = CameraFromInfo(info);
  EXPECT_DOUBLE_EQ(camera->fy(), 520.0);
  EXPECT_DOUBLE_EQ(camera->cx(), 319.5);
  EXPECT_DOUBLE_EQ(camera->distortion().k3, 0.05);
  info.distortion_model = "equidistant";
  EXPECT_THROW(CameraFromInfo(info), std::invalid_argument);
  info.K[0] = 0.0;
  EXPECT_THROW(CameraFromInfo(info), std::invalid_argument);
}

TEST(Conversions, DefaultMountFollowsRep103) {
  const Eigen::Isometry3d T = DefaultBaseFromOptical();
  EXPECT_TRUE((T * Eigen::Vector3d(0, 0, 1)).isApprox(Eigen::Vector3d(1, 0, 0)));   // forward
  EXPECT_TRUE((T * Eigen::Vector3d(1, 0, 0)).isApprox(Eigen::Vector3d(0, -1, 0)));  // right
  EXPECT_TRUE((T * Eigen::Vector3d(0, 1, 0)).isApprox(Eigen::Vector3d(0, 0, -1)));  // down
  // The camera moving 1 m along its optical axis moves the base 1 m forward in odom.
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  T_world_camera.translation() = Eigen::Vector3d(0, 0, 1);
  EXPECT_TRUE(OdomFromBase(T_world_camera, T).translation().isApprox(Eigen::Vector3d(1, 0, 0)));
}

TEST(Conversions, CovarianceMapsTranslationIntoBaseAxes) {
  // Information: translation along optical z (t of T_camera_world) known to 0.1 m, the rest
  // tightly. At the identity pose the odom x variance must then be 0.01 m^2.
  Eigen::Matrix<double, 6, 6> info = 1e8 * Eigen::Matrix<double, 6, 6>::Identity();
  info(5, 5) = 100.0;
  const auto cov = OdomCovariance(info, Eigen::Isometry3d::Identity(), DefaultBaseFromOptical());
  EXPECT_NEAR(cov(0, 0), 0.01, 1e-9);
  EXPECT_NEAR(cov(1, 1), 1e-8, 1e-12);
  EXPECT_TRUE(cov.isApprox(cov.transpose()));
  const auto unknown = OdomCovariance(Eigen::Matrix<double, 6, 6>::Zero(),
                                      Eigen::Isometry3d::Identity(), DefaultBaseFromOptical());
  EXPECT_DOUBLE_EQ(unknown(3, 3), 1e6);
}

}  // namespace
}  // namespace ros_layer
}  // namespace dslam
