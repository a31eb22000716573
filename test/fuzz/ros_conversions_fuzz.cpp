// Fuzz harness: the ROS layer's message conversions (dslam/ros/conversions.h): ColourFromImage,
// DepthFromImage, CameraFromInfo. Layout: mode byte (0 colour, 1 depth, 2 camera_info), then
//  images: encoding byte (an index into kEncodings, bogus names included), is_bigendian byte,
//    shape byte (even: width, height and step are 4 raw bytes each and the data is the rest;
//    odd: width and height are one byte each, step = width * pixel size + the step byte, and the
//    data is the rest cut or zero-padded to step * height), then the data;
//  camera_info: width, height (4 bytes each), distortion model byte (an index into kModels),
//    K (9 doubles), the count of D (byte % 10) and D's doubles.
#include <cmath>
#include <stdexcept>

#include <sensor_msgs/image_encodings.h>

#include "dslam/ros/conversions.h"
#include "fuzz_input.h"
#include "harnesses.h"

namespace dslam {
namespace fuzz {
namespace {

const char* const kEncodings[] = {"rgb8",  "bgr8",  "mono8",  "16UC1", "32FC1", "mono16",
                                  "bgra8", "rgba8", "8UC3",   "64FC1", "16SC1", "",
                                  "bogus", "8UC1",  "yuv422", "32FC",  "8UC0",  "bayer_rggb8"};
const char* const kModels[] = {"plumb_bob", "rational_polynomial", "equidistant", ""};

/// Bytes per pixel of an encoding cv_bridge knows, 1 for unknown names.
uint32_t PixelBytes(const std::string& encoding) {
  try {
    return sensor_msgs::image_encodings::bitDepth(encoding) / 8 *
           sensor_msgs::image_encodings::numChannels(encoding);
  } catch (const std::exception&) {
    return 1;
  }
}

sensor_msgs::Image MakeImage(FuzzInput& input) {
  sensor_msgs::Image image;
  image.encoding = kEncodings[input.Byte() % (sizeof(kEncodings) / sizeof(kEncodings[0]))];
  image.is_bigendian = input.Byte() % 2;
  if (input.Byte() % 2 == 0) {
    image.width = input.U32();
    image.height = input.U32();
    image.step = input.U32();
    const std::string rest = input.Rest();
    image.data.assign(rest.begin(), rest.end());
  } else {
    image.width = input.Byte();
    image.height = input.Byte();
    image.step = image.width * std::max<uint32_t>(PixelBytes(image.encoding), 1) + input.Byte();
    std::string rest = input.Rest();
    rest.resize(static_cast<size_t>(image.step) * image.height, '\0');
    image.data.assign(rest.begin(), rest.end());
  }
  return image;
}

void CheckImage(const cv::Mat& out, const sensor_msgs::Image& image, bool depth) {
  const bool type_ok =
      depth ? out.type() == CV_32FC1 : (out.type() == CV_8UC3 || out.type() == CV_8UC1);
  if (!type_ok || out.cols != static_cast<int>(image.width) ||
      out.rows != static_cast<int>(image.height)) {
    throw ContractViolation("converted " + image.encoding + " to type " +
                            std::to_string(out.type()) + " size " + std::to_string(out.cols) + "x" +
                            std::to_string(out.rows));
  }
  if (!depth) return;
  for (int r = 0; r < out.rows; ++r) {
    for (int c = 0; c < out.cols; ++c) {
      const float d = out.at<float>(r, c);
      if (!std::isfinite(d) || d < 0.0f) throw ContractViolation("depth " + std::to_string(d));
    }
  }
}

sensor_msgs::CameraInfo MakeInfo(FuzzInput& input) {
  sensor_msgs::CameraInfo info;
  info.width = input.U32();
  info.height = input.U32();
  info.distortion_model = kModels[input.Byte() % (sizeof(kModels) / sizeof(kModels[0]))];
  for (double& k : info.K) k = input.Double();
  for (double& p : info.P) p = input.Double();
  info.D.resize(input.Byte() % 10);
  for (double& d : info.D) d = input.Double();
  return info;
}

}  // namespace

void RosConversionsHarness(const std::string& data) {
  FuzzInput input(data);
  const int mode = input.Byte() % 3;
  if (mode == 2) {
    const sensor_msgs::CameraInfo info = MakeInfo(input);
    // The colour image the info comes with: mostly of the info's size, sometimes another.
    sensor_msgs::Image colour;
    const bool same_size = input.Byte() % 4 != 0;
    colour.width = same_size ? info.width : input.U32();
    colour.height = same_size ? info.height : input.U32();
    const ros_layer::ImageGeometry geometry =
        input.Byte() % 2 ? ros_layer::ImageGeometry::kRectified : ros_layer::ImageGeometry::kRaw;
    ParsedOrRejected<std::invalid_argument>(
        "", [&] { CheckCamera(*ros_layer::CameraFromInfo(info, colour, geometry)); });
    return;
  }
  const sensor_msgs::Image image = MakeImage(input);
  ParsedOrRejected<std::invalid_argument>("", [&] {
    if (mode == 0) {
      CheckImage(ros_layer::ColourFromImage(image), image, false);
    } else {
      CheckImage(ros_layer::DepthFromImage(image), image, true);
    }
  });
}

}  // namespace fuzz
}  // namespace dslam

DSLAM_FUZZ_TARGET(dslam::fuzz::RosConversionsHarness)
