#pragma once
// Bounds on the image sizes dslam accepts from files and messages (camera.yaml, camera_info,
// ROS images, depth PNGs), checked before anything of that size is allocated.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace dslam {

/// Largest image width or height accepted from a file or message [px].
constexpr int kMaxImageSidePx = 16384;

/// Largest pixel count of one image accepted from a file or message [px]: 2^25, which holds
/// 7680 x 4320 ("8K"); a 32-bit float depth image of that size takes 128 MiB.
constexpr int64_t kMaxImagePixels = int64_t{1} << 25;

/// Throws std::invalid_argument naming `what` when `width` or `height` [px] is below 1 or above
/// kMaxImageSidePx, or width * height is above kMaxImagePixels.
void CheckImageSize(int64_t width, int64_t height, const std::string& what);

/// Width and height [px] that a PNG's header (IHDR) declares, from the first `size` bytes at
/// `data`: nothing when they do not start with the PNG signature or are fewer than 24 (signature,
/// IHDR length and type, width and height).
std::optional<std::array<int64_t, 2>> PngHeaderSize(const unsigned char* data, std::size_t size);

/// Checks an image file before OpenCV decodes it: it must start with the PNG signature (or,
/// with `allow_jpeg`, the JPEG one), and a PNG's header (IHDR) must declare a size that passes
/// CheckImageSize. Throws std::runtime_error naming the file otherwise. cv::imread picks its
/// decoder by the file's first bytes, and some of Debian's decoders abort the process on a
/// malformed file (GDCM's DICOM reader asserts); dataset images are PNG (JPEG for colour). A file
/// that cannot be opened, is shorter than 8 bytes, or is a PNG shorter than its header passes (the
/// decoder reports it).
void CheckImageFile(const std::string& path, bool allow_jpeg);

}  // namespace dslam
