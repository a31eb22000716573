#include "dslam/ros/image_layout.h"

#include <cstdint>
#include <stdexcept>
#include <string>

#include <sensor_msgs/image_encodings.h>

#include "dslam/core/image_limits.h"

namespace dslam {
namespace ros_layer {

void CheckImageLayout(const sensor_msgs::Image& image) {
  const std::string what = "image '" + image.encoding + "'";
  CheckImageSize(image.width, image.height, what);
  namespace enc = sensor_msgs::image_encodings;
  const uint64_t value_bytes = static_cast<uint64_t>(enc::bitDepth(image.encoding) / 8);
  const uint64_t row_bytes = value_bytes * enc::numChannels(image.encoding) * image.width;
  if (image.step < row_bytes) {
    throw std::invalid_argument(what + ": step " + std::to_string(image.step) +
                                " bytes is less than a row of " + std::to_string(image.width) +
                                " pixels (" + std::to_string(row_bytes) + " bytes)");
  }
  if (value_bytes > 1 && image.step % value_bytes != 0) {
    throw std::invalid_argument(what + ": step " + std::to_string(image.step) +
                                " bytes is not a multiple of the value size (" +
                                std::to_string(value_bytes) + " bytes)");
  }
  const uint64_t expected = static_cast<uint64_t>(image.step) * image.height;
  if (image.data.size() != expected) {
    throw std::invalid_argument(what + ": data holds " + std::to_string(image.data.size()) +
                                " bytes, step * height is " + std::to_string(expected));
  }
}

}  // namespace ros_layer
}  // namespace dslam
