#pragma once
// Checks of a sensor_msgs/Image's size and layout before its data is read (cv_bridge reads
// step * height bytes at &data[0] without checking them against data.size() in 64 bits).

#include <sensor_msgs/Image.h>

namespace dslam {
namespace ros_layer {

/// Throws std::invalid_argument naming the encoding and the problem unless `image` has a size
/// within dslam/core/image_limits.h, a step of at least width times the encoding's bytes per
/// pixel and a multiple of its bytes per value (OpenCV's requirement), and exactly
/// step * height bytes of data. `image.encoding` must be one cv_bridge knows.
void CheckImageLayout(const sensor_msgs::Image& image);

}  // namespace ros_layer
}  // namespace dslam
