// The fuzz corpus and regression inputs of the io and core readers (test/fuzz/), replayed
// through the fuzz harnesses: each is parsed or rejected with the documented error.
#include <stdexcept>

#include "fuzz/fuzz_input.h"
#include "fuzz/harnesses.h"
#include "fuzz/replay.h"

namespace dslam {
namespace fuzz {
namespace {

TEST(FuzzReplay, CameraYaml) { ReplayStoredInputs("camera_yaml", CameraYamlHarness); }
TEST(FuzzReplay, ConfigYaml) { ReplayStoredInputs("config_yaml", ConfigYamlHarness); }
TEST(FuzzReplay, TumDataset) { ReplayStoredInputs("tum_dataset", TumDatasetHarness); }
TEST(FuzzReplay, Trajectory) { ReplayStoredInputs("trajectory", TrajectoryHarness); }
TEST(FuzzReplay, DepthConversion) {
  ReplayStoredInputs("depth_conversion", DepthConversionHarness);
}

// ParsedOrRejected turns an error message that does not name the file into ContractViolation and
// lets an exception of an undocumented type through: the replays above can fail.
TEST(FuzzReplay, HarnessRejectsBrokenContract) {
  EXPECT_THROW(ParsedOrRejected<std::runtime_error>(
                   "camera.yaml", [] { throw std::runtime_error("an error that names no file"); }),
               ContractViolation);
  EXPECT_THROW(ParsedOrRejected<std::runtime_error>("x", [] { throw std::logic_error("x"); }),
               std::logic_error);
}

}  // namespace
}  // namespace fuzz
}  // namespace dslam
