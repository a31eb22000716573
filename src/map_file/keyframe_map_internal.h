#pragma once
// Shared by the keyframe map file's writer, reader and checks (src/map_file/): the format's
// constants (dslam/map_file/keyframe_map_file.h), a bounded reader of the body, the content rules
// and the image encodings.

#include <cstddef>
#include <cstdint>
#include <string>

#include <Eigen/Geometry>

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

/// Reads the body from an offset on; every read past the end, and every count whose records
/// cannot fit in the bytes left, throws KeyFrameMapError "<name>: truncated body: ...".
class ByteReader {
 public:
  ByteReader(const std::string& bytes, std::size_t offset, const std::string& name)
      : bytes_(bytes), offset_(offset), name_(name) {}

  std::uint8_t U8(const char* what);
  std::uint32_t U32(const char* what);
  std::int32_t I32(const char* what) { return static_cast<std::int32_t>(U32(what)); }
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
  std::size_t offset() const { return offset_; }
  std::size_t left() const { return bytes_.size() - offset_; }

 private:
  /// Throws unless `n` bytes are left.
  void Need(std::size_t n, const char* what) const;

  const std::string& bytes_;
  std::size_t offset_;
  const std::string& name_;
};

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
