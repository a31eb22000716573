// The fuzz corpus and regression inputs of the ROS message conversions (test/fuzz/), replayed
// through the fuzz harness: each is converted or rejected with std::invalid_argument.
#include "fuzz/harnesses.h"
#include "fuzz/replay.h"

namespace dslam {
namespace fuzz {
namespace {

TEST(FuzzReplay, RosConversions) { ReplayStoredInputs("ros_conversions", RosConversionsHarness); }

}  // namespace
}  // namespace fuzz
}  // namespace dslam
