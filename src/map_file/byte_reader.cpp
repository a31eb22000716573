// The keyframe map file's bounded stream reader (keyframe_map_internal.h, ByteReader), its
// hashing writer (HashingWriter) and poses.
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

void ByteReader::Read(char* out, std::size_t n) {
  in_->read(out, static_cast<std::streamsize>(n));
  if (static_cast<std::size_t>(in_->gcount()) != n) {
    throw KeyFrameMapError(name_ + ": read error at offset " + std::to_string(offset_) +
                           " (the file ended early or changed while it was read)");
  }
  offset_ += n;
}

std::uint64_t ByteReader::LittleEndian(int n, const char* what) {
  Need(n, what);
  char bytes[8];
  Read(bytes, n);
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i)
    v |= static_cast<std::uint64_t>(static_cast<std::uint8_t>(bytes[i])) << (8 * i);
  return v;
}

std::uint8_t ByteReader::U8(const char* what) {
  return static_cast<std::uint8_t>(LittleEndian(1, what));
}

std::uint32_t ByteReader::U32(const char* what) {
  return static_cast<std::uint32_t>(LittleEndian(4, what));
}

std::uint64_t ByteReader::U64(const char* what) { return LittleEndian(8, what); }

std::int64_t ByteReader::I64(const char* what) {
  const std::uint64_t bits = LittleEndian(8, what);
  std::int64_t v = 0;
  std::memcpy(&v, &bits, sizeof(v));  // two's complement, without an out-of-range conversion
  return v;
}

double ByteReader::F64(const char* what) {
  const std::uint64_t bits = LittleEndian(8, what);
  double v = 0.0;
  std::memcpy(&v, &bits, sizeof(v));
  return v;
}

void ByteReader::F64s(double* out, int n, const char* what) {
  Need(8 * static_cast<std::size_t>(n), what);
  for (int i = 0; i < n; ++i) out[i] = F64(what);
}

std::string ByteReader::Bytes(std::size_t n, const char* what) {
  Need(n, what);
  std::string out(n, '\0');
  if (n > 0) Read(&out[0], n);
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

void HashingWriter::Write(std::string* bytes) {
  if (size_ + bytes->size() > kChecksumFrom) {
    const std::size_t skipped = size_ >= kChecksumFrom ? 0 : kChecksumFrom - size_;
    hash_ = Fnv1a64Update(hash_, bytes->data() + skipped, bytes->size() - skipped);
  }
  out_->write(bytes->data(), static_cast<std::streamsize>(bytes->size()));
  size_ += bytes->size();
  bytes->clear();
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
