#pragma once
// Shared by the keyframe map file's writer, reader and checks (src/map_file/): the format's
// constants (dslam/map_file/keyframe_map_file.h), a bounded reader of the body, the content rules
// and the image encodings.

#include <cstddef>
#include <cstdint>
#include <istream>
#include <ostream>
#include <streambuf>
#include <string>

#include <Eigen/Geometry>

#include "dslam/core/atomic_file.h"
#include "dslam/map_file/keyframe_map_file.h"

namespace dslam {
namespace map_file {

constexpr char kMagic[8] = {'D', 'S', 'L', 'A', 'M', 'K', 'F', 'M'};
constexpr std::size_t kChecksumFrom = 28;  ///< the checksum covers the bytes from here on
constexpr int kDescriptorBytes = 32;       ///< a map point's ORB descriptor
/// Smallest records [bytes]: a point without descriptor, a keyframe without points or
/// measurements, one measurement, an image pair with empty images.
constexpr std::size_t kMinPointBytes = 8 + 24 + 72 + 1 + 4 + 4 + 8 + 1 + 7 * 4;
constexpr std::size_t kMinKeyFrameBytes = 4 + 4 + 8 + 96 + 288 + 1 + 4 + 96 + 4;
constexpr std::size_t kMeasurementBytes = 8 + 24 + 72 + 8 + 8;
constexpr std::size_t kMinImagePairBytes = 4 + 4 + 4;
constexpr std::size_t kSettingsBytes = 4 + 6 * 8;  ///< the version 2 header's settings

/// Reads the records of a file of `size` bytes from a stream at `offset` on; every read past the
/// end, and every count whose records cannot fit in the bytes left, throws KeyFrameMapError
/// "<name>: truncated body: ..."; a stream that ends before `size` (a file cut while it is
/// read) throws "<name>: read error at offset N".
class ByteReader {
 public:
  ByteReader(std::istream* in, std::uint64_t offset, std::uint64_t size, const std::string& name)
      : in_(in), offset_(offset), size_(size), name_(name) {}

  std::uint8_t U8(const char* what);
  std::uint32_t U32(const char* what);
  std::int32_t I32(const char* what) { return static_cast<std::int32_t>(U32(what)); }
  std::uint64_t U64(const char* what);
  std::int64_t I64(const char* what);
  double F64(const char* what);
  /// `n` doubles into `out`.
  void F64s(double* out, int n, const char* what);
  /// `n` raw bytes.
  std::string Bytes(std::size_t n, const char* what);
  /// A u32 count of records of at least `min_record_bytes` each; throws when they cannot fit.
  std::uint32_t Count(std::size_t min_record_bytes, const char* what);
  /// Checks that `n` records of at least `min_record_bytes` can fit in the bytes left.
  void CheckFits(std::uint64_t n, std::size_t min_record_bytes, const char* what) const;
  std::uint64_t offset() const { return offset_; }
  std::uint64_t left() const { return size_ - offset_; }

 private:
  /// Throws unless `n` bytes are left.
  void Need(std::size_t n, const char* what) const;
  /// Reads `n` bytes (Need checked) into `out`.
  void Read(char* out, std::size_t n);
  /// The `n` (<= 8) bytes from here as a little-endian unsigned integer.
  std::uint64_t LittleEndian(int n, const char* what);

  std::istream* in_;
  std::uint64_t offset_;
  std::uint64_t size_;
  const std::string& name_;
};

/// A read-only std::streambuf over a string's bytes (no copy; `bytes` must outlive it).
class StringViewBuf : public std::streambuf {
 public:
  explicit StringViewBuf(const std::string& bytes) {
    char* begin = const_cast<char*>(bytes.data());
    setg(begin, begin, begin + bytes.size());
  }
};

/// Writes a file's bytes to a stream, hashing those from kChecksumFrom on as they pass (the
/// checksum of keyframe_map_file.h).
class HashingWriter {
 public:
  explicit HashingWriter(std::ostream* out) : out_(out) {}
  /// Writes `bytes` and clears it.
  void Write(std::string* bytes);
  std::uint64_t size() const { return size_; }      ///< [bytes] written so far
  std::uint64_t checksum() const { return hash_; }  ///< of the bytes from kChecksumFrom on
  bool ok() const { return static_cast<bool>(*out_); }

 private:
  std::ostream* out_;
  std::uint64_t size_ = 0;
  std::uint64_t hash_ = kFnv1a64Basis;
};

/// Writes the file of `file` (checked by the caller with CheckContents) to `out`, which must be
/// seekable: the size and checksum fields are written last.
void WriteKeyFrameMap(const KeyFrameMapFile& file, std::ostream* out);

/// The format version of a file of `size` bytes whose first bytes are `head` (the first
/// min(size, kKeyFrameMapHeaderBytes)): throws KeyFrameMapError for an empty file, another magic,
/// another version, a size shorter than the header or other than the header's size field.
std::uint32_t CheckHeader(const std::string& head, std::uint64_t size, const std::string& name);
/// Throws KeyFrameMapError "<name>: checksum mismatch: the file is corrupt" unless `checksum` is
/// the header's (`head` as for CheckHeader).
void CheckChecksum(const std::string& head, std::uint64_t checksum, const std::string& name);
/// The records of a file of format `version` and `size` bytes from `in`, positioned at
/// kChecksumFrom (header checked, checksum checked), checked with CheckContents.
KeyFrameMapFile ReadKeyFrameMap(std::istream* in, std::uint64_t size, std::uint32_t version,
                                const std::string& name);

/// Appends the 3x4 [R | t] of `T` (12 doubles, row-major).
void PutPose(const Eigen::Isometry3d& T, std::string* out);
/// Reads a pose PutPose wrote (the bottom row is 0 0 0 1).
Eigen::Isometry3d ReadPose(ByteReader* in, const char* what);

/// "" when `file` keeps the rules of SerialiseKeyFrameMap (keyframe_map_file.h), else the first
/// rule it breaks, naming the point or keyframe.
std::string CheckContents(const KeyFrameMapFile& file);

/// The PNG bytes of a colour image (CV_8UC3 or CV_8UC1, lossless).
std::string EncodeColour(const cv::Mat& colour);
/// The PNG bytes of depth [m] (CV_32FC1) as 16-bit millimetres (rounding: keyframe_map_file.h).
std::string EncodeDepth(const cv::Mat& depth_m);
/// Decodes an image pair of keyframe `id`; throws KeyFrameMapError "<name>: invalid content: ..."
/// when a byte string is not a PNG of the camera's size and the documented type.
KeyFrameImages DecodeImages(const std::string& colour_png, const std::string& depth_png,
                            const PinholeCamera& camera, int id, const std::string& name);

}  // namespace map_file
}  // namespace dslam
