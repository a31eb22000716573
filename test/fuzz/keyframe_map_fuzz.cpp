// Fuzz harness: keyframe map file bytes (dslam/map_file/keyframe_map_file.h, ParseKeyFrameMap),
// as they are and resealed (keyframe_map_seal.h: size and checksum made right, so that mutations
// of the body reach the body parser).
#include <stdexcept>

#include "dslam/map_file/keyframe_map_file.h"
#include "fuzz_input.h"
#include "harnesses.h"
#include "keyframe_map_seal.h"

namespace dslam {
namespace fuzz {
namespace {

/// Throws ContractViolation unless `file` keeps what ParseKeyFrameMap documents: ids not
/// negative and ascending, a valid camera, descriptors empty or 1x32 CV_8U, images of map
/// keyframes with the camera's size, and contents the writer accepts again; without images (which
/// it re-encodes) it writes `bytes` back exactly.
void CheckParsed(const KeyFrameMapFile& file, const std::string& bytes) {
  CheckCamera(file.camera);
  const auto& points = file.contents.points;
  for (size_t i = 0; i < points.size(); ++i) {
    if (points[i].id < 0 || (i > 0 && points[i].id <= points[i - 1].id)) {
      throw ContractViolation("accepted point id " + std::to_string(points[i].id));
    }
    const cv::Mat& d = points[i].descriptor;
    if (!d.empty() && (d.rows != 1 || d.cols != 32 || d.type() != CV_8U)) {
      throw ContractViolation("accepted a descriptor of another shape");
    }
  }
  const auto& keyframes = file.contents.keyframes;
  for (size_t i = 0; i < keyframes.size(); ++i) {
    if (keyframes[i].id < 0 || (i > 0 && keyframes[i].id <= keyframes[i - 1].id)) {
      throw ContractViolation("accepted keyframe id " + std::to_string(keyframes[i].id));
    }
  }
  for (const auto& entry : file.images) {
    const cv::Size size(file.camera.width(), file.camera.height());
    if (entry.second.colour.size() != size || entry.second.depth_m.size() != size ||
        entry.second.depth_m.type() != CV_32FC1) {
      throw ContractViolation("accepted images of another size or type");
    }
  }
  std::string written;
  try {
    written = SerialiseKeyFrameMap(file);
  } catch (const std::invalid_argument& e) {
    throw ContractViolation(std::string("the writer refuses what the reader accepted: ") +
                            e.what());
  }
  if (file.images.empty() && written != bytes) {
    throw ContractViolation("the writer writes other bytes than the reader accepted");
  }
}

void ParseOnce(const std::string& bytes) {
  ParsedOrRejected<KeyFrameMapError>(
      "kfm.bin", [&] { CheckParsed(ParseKeyFrameMap(bytes, "kfm.bin"), bytes); });
}

}  // namespace

void KeyFrameMapHarness(const std::string& data) {
  ParseOnce(data);
  ParseOnce(Resealed(data));
}

}  // namespace fuzz
}  // namespace dslam

DSLAM_FUZZ_TARGET(dslam::fuzz::KeyFrameMapHarness)
