// Fuzz harness: camera.yaml text (dslam/io/dataset_io.h, ParseCameraYaml).
#include <yaml-cpp/exceptions.h>

#include <cmath>
#include <stdexcept>

#include "dslam/io/dataset_io.h"
#include "fuzz_input.h"
#include "harnesses.h"

namespace dslam {
namespace fuzz {

void CameraYamlHarness(const std::string& data) {
  ParsedOrRejected<std::runtime_error>("camera.yaml", [&] {
    CameraYaml parsed;
    try {
      parsed = ParseCameraYaml(data, "camera.yaml");
    } catch (const YAML::Exception& e) {
      throw ContractViolation(std::string("yaml-cpp exception escaped: ") + e.what());
    }
    if (!parsed.camera) throw ContractViolation("no camera");
    CheckCamera(*parsed.camera);
    if (!(std::isfinite(parsed.depth_scale) && parsed.depth_scale > 0.0)) {
      throw ContractViolation("accepted depth_scale " + std::to_string(parsed.depth_scale));
    }
  });
}

}  // namespace fuzz
}  // namespace dslam

DSLAM_FUZZ_TARGET(dslam::fuzz::CameraYamlHarness)
