#pragma once
// The fuzz harnesses: each feeds one input (the fuzz bytes) to dslam's readers and converters
// and returns when the input was parsed with results the readers document, or rejected with
// the exception type and message they document. Otherwise it throws ContractViolation (or lets
// the unexpected exception through), which libFuzzer reports as a crash. The bytes' layout is
// described per harness; scripts/fuzz.sh builds each as one libFuzzer target.

#include <string>

namespace dslam {
namespace fuzz {

/// camera.yaml text -> ParseCameraYaml.
void CameraYamlHarness(const std::string& data);

/// Config YAML text -> LoadConfigYamlString.
void ConfigYamlHarness(const std::string& data);

/// TUM folder: "camera.yaml NUL rgb.txt NUL depth.txt", written to a temporary folder that
/// TumDataset then opens (association tolerance 0.02 s).
void TumDatasetHarness(const std::string& data);

/// TUM trajectory text -> ParseTumTrajectory.
void TrajectoryHarness(const std::string& data);

/// Core depth conversion: a mode byte (scaled 16-bit, metres, or a depth PNG file), an OpenCV
/// type, rows, cols, the scale's 8 bytes, then the pixel bytes (or the PNG file's bytes).
void DepthConversionHarness(const std::string& data);

/// Keyframe map file bytes -> ParseKeyFrameMap, as they are and with the header's size and
/// checksum made right (keyframe_map_seal.h).
void KeyFrameMapHarness(const std::string& data);

/// ROS layer: a mode byte (colour image, depth image, camera_info), then the message's fields
/// (see ros_conversions_fuzz.cpp).
void RosConversionsHarness(const std::string& data);

}  // namespace fuzz
}  // namespace dslam

/// The libFuzzer entry point of a harness (compiled only in the fuzz build).
#ifdef DSLAM_LIBFUZZER
#include <cstddef>
#include <cstdint>
#define DSLAM_FUZZ_TARGET(harness)                                          \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { \
    harness(std::string(reinterpret_cast<const char*>(data), size));        \
    return 0;                                                               \
  }
#else
#define DSLAM_FUZZ_TARGET(harness)
#endif
