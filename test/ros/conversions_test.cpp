#include "dslam/ros/conversions.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

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

/// The message of the std::invalid_argument `f` throws; "" when it throws nothing.
template <typename F>
std::string ErrorOf(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

template <typename T>
void Put(sensor_msgs::Image* image, const std::vector<T>& values) {
  image->data.resize(values.size() * sizeof(T));
  std::memcpy(image->data.data(), values.data(), image->data.size());
}

TEST(Conversions, DepthMillimetresAndMetres) {
  sensor_msgs::Image mm = MakeImage(2, 1, "16UC1", 2);
  Put<uint16_t>(&mm, {1500, 0});
  const cv::Mat a = DepthFromImage(mm);
  EXPECT_FLOAT_EQ(a.at<float>(0, 0), 1.5f);
  EXPECT_FLOAT_EQ(a.at<float>(0, 1), 0.0f);
  mm.encoding = "mono16";
  EXPECT_FLOAT_EQ(DepthFromImage(mm).at<float>(0, 0), 1.5f);

  sensor_msgs::Image m = MakeImage(5, 1, "32FC1", 4);
  const float inf = std::numeric_limits<float>::infinity();
  Put<float>(&m, {2.25f, std::numeric_limits<float>::quiet_NaN(), -1.0f, inf, -inf});
  const cv::Mat b = DepthFromImage(m);
  EXPECT_FLOAT_EQ(b.at<float>(0, 0), 2.25f);
  for (int c = 1; c < 5; ++c) EXPECT_FLOAT_EQ(b.at<float>(0, c), 0.0f) << c;
}

TEST(Conversions, UnsupportedDepthEncodingIsNamed) {
  for (const char* encoding : {"rgb8", "8UC1", "16SC1", "64FC1"}) {
    EXPECT_EQ(ErrorOf([&] { DepthFromImage(MakeImage(2, 2, encoding, 1)); }),
              std::string("depth image encoding '") + encoding +
                  "' is not supported (accepted: 16UC1 or mono16 millimetres, 32FC1 metres)");
  }
}

TEST(Conversions, BigEndianDepthIsByteSwapped) {
  sensor_msgs::Image mm = MakeImage(2, 1, "16UC1", 2);
  mm.is_bigendian = 1;
  mm.data = {0x05, 0xDC, 0x00, 0x00};  // 1500 (0x05DC) most significant byte first, 0
  const cv::Mat a = DepthFromImage(mm);
  EXPECT_FLOAT_EQ(a.at<float>(0, 0), 1.5f);
  EXPECT_FLOAT_EQ(a.at<float>(0, 1), 0.0f);

  sensor_msgs::Image m = MakeImage(1, 1, "32FC1", 4);
  m.is_bigendian = 1;
  m.data = {0x40, 0x10, 0x00, 0x00};  // IEEE 754 2.25f, most significant byte first
  EXPECT_FLOAT_EQ(DepthFromImage(m).at<float>(0, 0), 2.25f);
}

TEST(Conversions, PaddedRowsAreReadByStep) {
  sensor_msgs::Image mm = MakeImage(2, 2, "16UC1", 2);
  mm.step = 6;  // 4 bytes of pixels and 2 of padding per row
  mm.data = {0xE8, 0x03, 0xD0, 0x07, 0xFF, 0xFF, 0xB8, 0x0B, 0xA0, 0x0F, 0xFF, 0xFF};
  const cv::Mat depth = DepthFromImage(mm);
  EXPECT_FLOAT_EQ(depth.at<float>(0, 1), 2.0f);
  EXPECT_FLOAT_EQ(depth.at<float>(1, 0), 3.0f);
  EXPECT_FLOAT_EQ(depth.at<float>(1, 1), 4.0f);
}

TEST(Conversions, TruncatedOrInconsistentImagesAreRejectedBeforeReading) {
  sensor_msgs::Image depth = MakeImage(640, 480, "16UC1", 2);
  depth.data.resize(depth.data.size() / 2);  // a truncated message: half of the rows
  EXPECT_EQ(ErrorOf([&] { DepthFromImage(depth); }),
            "depth image (16UC1) is truncated: 307200 data bytes, step x height = 614400");
  depth.data.resize(depth.data.size() * 3);  // more data than step x height: a wrong height?
  EXPECT_EQ(ErrorOf([&] { DepthFromImage(depth); }),
            "depth image (16UC1) is inconsistent: 921600 data bytes, step x height = 614400");
  sensor_msgs::Image colour = MakeImage(640, 480, "rgb8", 3);
  colour.step = 640;  // one byte per pixel for a 3-byte encoding
  EXPECT_EQ(ErrorOf([&] { ColourFromImage(colour); }),
            "colour image (rgb8) step 640 is shorter than a row (640 px x 3 bytes of rgb8)");
  EXPECT_EQ(ErrorOf([&] { ColourFromImage(MakeImage(0, 480, "bgr8", 3)); }),
            "colour image (bgr8) is empty (0x480)");
  EXPECT_EQ(ErrorOf([&] { DepthFromImage(MakeImage(640, 0, "32FC1", 4)); }),
            "depth image (32FC1) is empty (640x0)");
}

TEST(Conversions, ColourEncodingsBecomeBgrOrGrey) {
  sensor_msgs::Image rgb = MakeImage(1, 1, "rgb8", 3);
  rgb.data = {10, 20, 30};
  EXPECT_EQ(ColourFromImage(rgb).at<cv::Vec3b>(0, 0), cv::Vec3b(30, 20, 10));
  sensor_msgs::Image bgr = MakeImage(1, 1, "bgr8", 3);
  bgr.data = {10, 20, 30};
  EXPECT_EQ(ColourFromImage(bgr).at<cv::Vec3b>(0, 0), cv::Vec3b(10, 20, 30));
  sensor_msgs::Image rgba = MakeImage(1, 1, "rgba8", 4);
  rgba.data = {10, 20, 30, 255};
  EXPECT_EQ(ColourFromImage(rgba).at<cv::Vec3b>(0, 0), cv::Vec3b(30, 20, 10));
  sensor_msgs::Image bgra = MakeImage(1, 1, "bgra8", 4);
  bgra.data = {10, 20, 30, 0};
  EXPECT_EQ(ColourFromImage(bgra).at<cv::Vec3b>(0, 0), cv::Vec3b(10, 20, 30));
  EXPECT_EQ(ColourFromImage(rgba).type(), CV_8UC3);
  EXPECT_EQ(ColourFromImage(MakeImage(4, 3, "mono8", 1)).type(), CV_8UC1);
}

TEST(Conversions, UnsupportedColourEncodingIsNamedWithTheAcceptedOnes) {
  for (const char* encoding : {"bayer_grbg8", "yuv422", "rgb16", "16UC1"}) {
    EXPECT_EQ(ErrorOf([&] { ColourFromImage(MakeImage(2, 2, encoding, 2)); }),
              std::string("colour image encoding '") + encoding +
                  "' is not supported (accepted: rgb8, bgr8, rgba8, bgra8, mono8; subscribe to a "
                  "debayered topic such as image_color)");
  }
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

TEST(Conversions, MapFromOdomChainsWithOdomFromBase) {
  // A mount as TF gives it (a rotation whose product with its inverse has round-off).
  const Eigen::Isometry3d T_base_camera =
      Eigen::Translation3d(0.1, -0.02, 0.3) * DefaultBaseFromOptical() *
      Eigen::AngleAxisd(0.1234, Eigen::Vector3d(1.0, 0.3, -0.2).normalized());
  EXPECT_TRUE(MapFromOdom(Eigen::Isometry3d::Identity(), T_base_camera).matrix() ==
              Eigen::Matrix4d::Identity());
  // map -> odom -> base in base frames gives the camera's pose in the map, the map being the
  // base at the tracker's first frame as odom is the base where odom started.
  const Eigen::Isometry3d T_map_odom =
      Eigen::Translation3d(0.02, 0.01, -0.03) * Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitY());
  const Eigen::Isometry3d T_odom_camera =
      Eigen::Translation3d(0.5, -0.1, 2.0) * Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitY());
  EXPECT_TRUE((MapFromOdom(T_map_odom, T_base_camera) * OdomFromBase(T_odom_camera, T_base_camera))
                  .isApprox(OdomFromBase(T_map_odom * T_odom_camera, T_base_camera), 1e-12));
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
