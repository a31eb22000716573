#pragma once
// Bounds on the image sizes dslam accepts from files and messages (camera.yaml, camera_info,
// ROS images, depth PNGs), checked before anything of that size is allocated.

#include <cstdint>
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

/// When the file at `path` starts with the PNG signature, checks the size in its header (IHDR)
/// with CheckImageSize before a decoder allocates that size; throws std::runtime_error naming
/// the file. Other files, and files that cannot be opened, pass (their reader reports them).
void CheckPngFileSize(const std::string& path);

}  // namespace dslam
