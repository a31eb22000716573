// The keyframe map file's bounded body reader (keyframe_map_internal.h, ByteReader) and poses.
#include <cstring>

#include "dslam/core/binary_io.h"
#include "keyframe_map_internal.h"

namespace dslam {
namespace map_file {

void ByteReader::Need(std::size_t n, const char* what) const {
  if (n > left()) {
    throw KeyFrameMapError(name_ + ": truncated body: " + what + " needs " + std::to_string(n) +
                           " bytes at offset " + std::to_string(offset_) + ", " +
                           std::to_string(left()) + " are left");
  }
}

std::uint8_t ByteReader::U8(const char* what) {
  Need(1, what);
  return static_cast<std::uint8_t>(bytes_[offset_++]);
}

std::uint32_t ByteReader::U32(const char* what) {
  Need(4, what);
  const auto v = static_cast<std::uint32_t>(GetLittleEndian(bytes_, offset_, 4));
  offset_ += 4;
  return v;
}

std::int64_t ByteReader::I64(const char* what) {
  Need(8, what);
  const std::uint64_t bits = GetLittleEndian(bytes_, offset_, 8);
  offset_ += 8;
  std::int64_t v = 0;
  std::memcpy(&v, &bits, sizeof(v));  // two's complement, without an out-of-range conversion
  return v;
}

double ByteReader::F64(const char* what) {
  Need(8, what);
  const double v = GetF64(bytes_, offset_);
  offset_ += 8;
  return v;
}

void ByteReader::F64s(double* out, int n, const char* what) {
  Need(8 * static_cast<std::size_t>(n), what);
  for (int i = 0; i < n; ++i) out[i] = F64(what);
}

std::string ByteReader::Bytes(std::size_t n, const char* what) {
  Need(n, what);
  std::string out = bytes_.substr(offset_, n);
  offset_ += n;
  return out;
}

void ByteReader::CheckFits(std::uint64_t n, std::size_t min_record_bytes, const char* what) const {
  if (n > left() / min_record_bytes) {
    throw KeyFrameMapError(name_ + ": truncated body: " + std::to_string(n) + " " + what +
                           " of at least " + std::to_string(min_record_bytes) +
                           " bytes each at offset " + std::to_string(offset_) + ", " +
                           std::to_string(left()) + " bytes are left");
  }
}

std::uint32_t ByteReader::Count(std::size_t min_record_bytes, const char* what) {
  const std::uint32_t n = U32(what);
  CheckFits(n, min_record_bytes, what);
  return n;
}

Eigen::Isometry3d ReadPose(ByteReader* in, const char* what) {
  double v[12];
  in->F64s(v, 12, what);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) T.matrix()(r, c) = v[4 * r + c];
  }
  return T;
}

}  // namespace map_file
}  // namespace dslam
