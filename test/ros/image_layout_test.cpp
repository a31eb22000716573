// sensor_msgs/Image sizes and layouts that fuzzing (test/fuzz/) found to crash the conversions
// (cv_bridge or OpenCV exceptions, reads past the data): each is rejected with
// std::invalid_argument naming the problem before cv_bridge sees the message.
#include "dslam/ros/image_layout.h"

#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "dslam/ros/conversions.h"

namespace dslam {
namespace ros_layer {
namespace {

sensor_msgs::Image Image(uint32_t width, uint32_t height, uint32_t step, size_t bytes,
                         const std::string& encoding) {
  sensor_msgs::Image image;
  image.width = width;
  image.height = height;
  image.step = step;
  image.encoding = encoding;
  image.data.assign(bytes, 0);
  return image;
}

/// The message of the std::invalid_argument `f` throws ("" for none).
template <typename F>
std::string ErrorOf(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ImageLayout, AcceptsPaddedRows) {
  const sensor_msgs::Image image = Image(3, 2, 16, 32, "32FC1");
  EXPECT_NO_THROW(CheckImageLayout(image));
  EXPECT_EQ(DepthFromImage(image).size(), cv::Size(3, 2));
}

TEST(ImageLayout, RejectsEmptyAndAbsurdSizes) {
  // An empty rgb8 image reached cv::cvtColor, which threw cv::Exception.
  EXPECT_NE(ErrorOf([] { ColourFromImage(Image(0, 0, 0, 0, "rgb8")); }).find("empty"),
            std::string::npos);
  EXPECT_NE(
      ErrorOf([] { DepthFromImage(Image(4000000000u, 1, 0, 0, "16UC1")); }).find("side above"),
      std::string::npos);
}

TEST(ImageLayout, RejectsStepsAndDataThatDoNotMatch) {
  EXPECT_NE(ErrorOf([] { CheckImageLayout(Image(4, 2, 11, 22, "rgb8")); }).find("step 11"),
            std::string::npos);
  // A 32FC1 step that is no multiple of 4 made OpenCV throw cv::Exception.
  EXPECT_NE(ErrorOf([] { DepthFromImage(Image(3, 2, 14, 28, "32FC1")); }).find("multiple"),
            std::string::npos);
  // Fewer bytes than step * height: cv_bridge would read past the data.
  EXPECT_NE(ErrorOf([] {
              ColourFromImage(Image(4, 3, 12, 35, "rgb8"));
            }).find("data holds 35 bytes, step * height is 36"),
            std::string::npos);
  // step * height wraps around in 32 bits (2 * 2^31 = 0 bytes of data).
  EXPECT_NE(ErrorOf([] {
              CheckImageLayout(Image(2, 2, 2147483648u, 0, "mono8"));
            }).find("step * height is 4294967296"),
            std::string::npos);
}

}  // namespace
}  // namespace ros_layer
}  // namespace dslam
