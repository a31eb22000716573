// Fuzz harness: the core depth conversion (dslam/core/depth_conversion.h). Layout: mode byte
// (0 DepthFromScaledUint16, 1 DepthFromMetres, 2 ReadDepthPng of a file), type byte (an index
// into kTypes), rows byte, cols byte, scale (8 bytes of a double), then the pixel bytes (mode 2:
// the file's bytes).
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <opencv2/core.hpp>

#include "dslam/core/depth_conversion.h"
#include "fuzz_input.h"
#include "harnesses.h"

namespace dslam {
namespace fuzz {
namespace {

const int kTypes[] = {CV_16UC1, CV_32FC1, CV_16SC1, CV_8UC1, CV_64FC1, CV_16UC3, CV_32FC2};

/// Throws ContractViolation unless `depth` is CV_32FC1 of `size` with finite values >= 0, and
/// (when `zero_iff` is given) zero exactly where `zero_iff` is zero.
void CheckDepth(const cv::Mat& depth, const cv::Size& size, const cv::Mat& zero_iff = cv::Mat()) {
  if (depth.type() != CV_32FC1 || depth.size() != size) {
    throw ContractViolation("depth of type " + std::to_string(depth.type()) + " and size " +
                            std::to_string(depth.cols) + "x" + std::to_string(depth.rows));
  }
  for (int r = 0; r < depth.rows; ++r) {
    for (int c = 0; c < depth.cols; ++c) {
      const float d = depth.at<float>(r, c);
      if (!std::isfinite(d) || d < 0.0f) {
        throw ContractViolation("depth value " + std::to_string(d));
      }
      if (!zero_iff.empty() && (d == 0.0f) != (zero_iff.at<uint16_t>(r, c) == 0)) {
        throw ContractViolation("depth " + std::to_string(d) + " from raw value " +
                                std::to_string(zero_iff.at<uint16_t>(r, c)));
      }
    }
  }
  if (CountValidDepth(depth) > depth.rows * depth.cols) throw ContractViolation("valid count");
}

/// A temporary file of this process, removed at exit.
class TempFile {
 public:
  TempFile() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/dslam_fuzz_depth_XXXXXX";
    const int fd = mkstemp(pattern.data());
    if (fd < 0) throw std::runtime_error("mkstemp failed: " + pattern);
    close(fd);
    path_ = pattern;
  }
  ~TempFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

void FromPng(const std::string& bytes, double scale) {
  static const TempFile file;
  {
    std::ofstream out(file.path(), std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  cv::Mat depth;
  try {
    depth = ReadDepthPng(file.path(), scale);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(e.what());  // both types are documented; judged below as one
  }
  if (depth.empty()) throw ContractViolation("empty depth from a PNG");
  CheckDepth(depth, depth.size());
}

}  // namespace

void DepthConversionHarness(const std::string& data) {
  FuzzInput input(data);
  const int mode = input.Byte() % 3;
  const int type = kTypes[input.Byte() % (sizeof(kTypes) / sizeof(kTypes[0]))];
  const int rows = input.Byte(), cols = input.Byte();
  const double scale = input.Double();
  std::string pixels = input.Rest();
  if (mode == 2) {
    ParsedOrRejected<std::runtime_error>("", [&] { FromPng(pixels, scale); });
    return;
  }
  cv::Mat raw(rows, cols, type);
  const size_t bytes = raw.total() * raw.elemSize();
  pixels.resize(bytes, '\0');
  if (bytes > 0) std::memcpy(raw.data, pixels.data(), bytes);
  ParsedOrRejected<std::invalid_argument>("depth", [&] {
    if (mode == 0) {
      const cv::Mat depth = DepthFromScaledUint16(raw, scale);
      CheckDepth(depth, raw.size(), raw);
    } else {
      CheckDepth(DepthFromMetres(raw), raw.size());
    }
  });
}

}  // namespace fuzz
}  // namespace dslam

DSLAM_FUZZ_TARGET(dslam::fuzz::DepthConversionHarness)
