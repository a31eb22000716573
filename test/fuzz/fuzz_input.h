#pragma once
// Shared by the fuzz harnesses (test/fuzz/*_fuzz.cpp): reading typed values from fuzz bytes, the
// "parsed or rejected cleanly" contract, and checks of what a caller may rely on after a parse.
// The harnesses run under libFuzzer (scripts/fuzz.sh) and, on the stored corpus and regression
// files, in the normal gtest build (test/io/fuzz_replay_test.cpp, test/ros/fuzz_replay_test.cpp).

#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>

#include "dslam/core/camera.h"
#include "dslam/core/image_limits.h"

namespace dslam {
namespace fuzz {

/// Thrown by a harness when the code under test broke its contract: an exception of a type it
/// does not document, an error message that does not name what it read, or a result that
/// violates its documented guarantees. Not derived from std::runtime_error / logic_error, so no
/// documented catch clause takes it; under libFuzzer it terminates the run (a crash).
class ContractViolation : public std::exception {
 public:
  explicit ContractViolation(std::string message) : message_(std::move(message)) {}
  const char* what() const noexcept override { return message_.c_str(); }

 private:
  std::string message_;
};

/// Reads fixed-size values from the front of the fuzz bytes; past the end, values are 0.
class FuzzInput {
 public:
  explicit FuzzInput(const std::string& data) : data_(data) {}

  size_t remaining() const { return data_.size() - pos_; }
  uint8_t Byte() { return pos_ < data_.size() ? static_cast<uint8_t>(data_[pos_++]) : 0; }
  uint32_t U32() {
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(Byte()) << (8 * i);
    return v;
  }
  /// Eight bytes as the bit pattern of a double (any value: NaN, infinities, denormals).
  double Double() {
    uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= static_cast<uint64_t>(Byte()) << (8 * i);
    double v;
    std::memcpy(&v, &bits, sizeof(v));
    return v;
  }
  /// The bytes up to the next NUL (which is consumed), or all remaining bytes.
  std::string UntilNul() {
    const size_t end = data_.find('\0', pos_);
    const size_t stop = end == std::string::npos ? data_.size() : end;
    std::string out = data_.substr(pos_, stop - pos_);
    pos_ = end == std::string::npos ? data_.size() : end + 1;
    return out;
  }
  std::string Rest() {
    std::string out = data_.substr(pos_);
    pos_ = data_.size();
    return out;
  }

 private:
  const std::string& data_;
  size_t pos_ = 0;
};

/// Runs `parse`. Returns true when it returned, false when it threw `Documented` with a message
/// that contains `name` (the file name the caller passed; "" for none). An exception of another
/// type propagates (a harness failure), and so does ContractViolation.
template <typename Documented, typename Parse>
bool ParsedOrRejected(const std::string& name, Parse&& parse) {
  try {
    parse();
    return true;
  } catch (const Documented& e) {
    const std::string message = e.what();
    if (message.empty() || message.find(name) == std::string::npos) {
      throw ContractViolation("error message does not name '" + name + "': '" + message + "'");
    }
    return false;
  }
}

/// Throws ContractViolation unless `camera` has a size within the image limits and finite,
/// positive focal lengths, a finite principal point and finite distortion.
inline void CheckCamera(const PinholeCamera& camera) {
  const Distortion& d = camera.distortion();
  const bool ok = camera.width() >= 1 && camera.height() >= 1 &&
                  camera.width() <= kMaxImageSidePx && camera.height() <= kMaxImageSidePx &&
                  std::isfinite(camera.fx()) && camera.fx() > 0.0 && std::isfinite(camera.fy()) &&
                  camera.fy() > 0.0 && std::isfinite(camera.cx()) && std::isfinite(camera.cy()) &&
                  std::isfinite(d.k1) && std::isfinite(d.k2) && std::isfinite(d.p1) &&
                  std::isfinite(d.p2) && std::isfinite(d.k3);
  if (!ok) {
    throw ContractViolation("accepted camera " + std::to_string(camera.width()) + "x" +
                            std::to_string(camera.height()) + " fx " + std::to_string(camera.fx()) +
                            " fy " + std::to_string(camera.fy()) + " cx " +
                            std::to_string(camera.cx()) + " cy " + std::to_string(camera.cy()));
  }
}

}  // namespace fuzz
}  // namespace dslam
