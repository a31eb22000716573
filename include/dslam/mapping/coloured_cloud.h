#pragma once
// The static map's output: coloured points, and their PCD files (x y z rgb, the fields PCL's
// PointXYZRGB writes).

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace dslam {

/// One map point with its colour.
struct ColouredPoint {
  Eigen::Vector3f p = Eigen::Vector3f::Zero();  ///< [m] position, in the cloud's frame
  uint8_t r = 0, g = 0, b = 0;                  ///< colour, 0-255 per channel
};

/// A cloud of coloured points; its frame is stated where it is produced.
using ColouredCloud = std::vector<ColouredPoint>;

/// Writes `cloud` as a binary PCD file with fields x y z rgb (metres; rgb packed as PCL's
/// PointXYZRGB). Throws std::runtime_error naming `path` when it cannot be written.
void WritePcd(const std::string& path, const ColouredCloud& cloud);

/// Reads a PCD file with fields x y z and, when present, rgb. Throws std::runtime_error naming
/// `path` when it cannot be read.
ColouredCloud ReadPcd(const std::string& path);

}  // namespace dslam
