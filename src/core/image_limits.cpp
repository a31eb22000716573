#include "dslam/core/image_limits.h"

#include <array>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace dslam {

void CheckImageSize(int64_t width, int64_t height, const std::string& what) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width < 1 || height < 1) {
    throw std::invalid_argument(what + ": image size " + size + " is empty");
  }
  if (width > kMaxImageSidePx || height > kMaxImageSidePx) {
    throw std::invalid_argument(what + ": image size " + size + " has a side above " +
                                std::to_string(kMaxImageSidePx) + " px");
  }
  if (width * height > kMaxImagePixels) {
    throw std::invalid_argument(what + ": image size " + size + " has more than " +
                                std::to_string(kMaxImagePixels) + " pixels");
  }
}

void CheckPngFileSize(const std::string& path) {
  // Signature (8 bytes), IHDR length and type (8 bytes), width and height (big-endian uint32).
  std::array<unsigned char, 24> header{};
  std::ifstream in(path, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(header.data()), header.size())) return;
  const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (std::memcmp(header.data(), kSignature, sizeof(kSignature)) != 0) return;
  const auto be32 = [&](int at) {
    return (int64_t{header[at]} << 24) | (int64_t{header[at + 1]} << 16) |
           (int64_t{header[at + 2]} << 8) | int64_t{header[at + 3]};
  };
  try {
    CheckImageSize(be32(16), be32(20), "PNG header");
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

}  // namespace dslam
