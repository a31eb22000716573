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

std::optional<std::array<int64_t, 2>> PngHeaderSize(const unsigned char* data, std::size_t size) {
  // Signature (8 bytes), IHDR length and type (8 bytes), width and height (big-endian uint32).
  const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size < 24 || std::memcmp(data, kPng, sizeof(kPng)) != 0) return std::nullopt;
  const auto be32 = [&](int at) {
    return (int64_t{data[at]} << 24) | (int64_t{data[at + 1]} << 16) |
           (int64_t{data[at + 2]} << 8) | int64_t{data[at + 3]};
  };
  return std::array<int64_t, 2>{be32(16), be32(20)};
}

void CheckImageFile(const std::string& path, bool allow_jpeg) {
  std::array<unsigned char, 24> header{};
  std::ifstream in(path, std::ios::binary);
  if (!in) return;
  in.read(reinterpret_cast<char*>(header.data()), header.size());
  const std::streamsize read = in.gcount();
  const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  const unsigned char kJpeg[3] = {0xff, 0xd8, 0xff};
  if (read >= 3 && allow_jpeg && std::memcmp(header.data(), kJpeg, sizeof(kJpeg)) == 0) return;
  if (read < 8) return;
  if (std::memcmp(header.data(), kPng, sizeof(kPng)) != 0) {
    throw std::runtime_error(path + ": not a PNG" + (allow_jpeg ? " or JPEG" : "") + " file");
  }
  const auto size = PngHeaderSize(header.data(), static_cast<std::size_t>(read));
  if (!size) return;
  try {
    CheckImageSize((*size)[0], (*size)[1], "PNG header");
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

}  // namespace dslam
