// The keyframe map harness's seed corpus (test/fuzz/corpus/keyframe_map/, the sample maps of
// map_file/sample_map.h) and regression inputs, replayed through the fuzz harness; the seeds are
// checked to be the sample maps (DSLAM_WRITE_FUZZ_SEEDS=1 rewrites them).
#include <cstdlib>
#include <fstream>

#include "dslam/core/binary_io.h"
#include "fuzz/fuzz_input.h"
#include "fuzz/harnesses.h"
#include "fuzz/replay.h"
#include "map_file/sample_map.h"

namespace dslam {
namespace fuzz {
namespace {

struct Seed {
  const char* name;
  int points, keyframes;
  bool images;
  bool version_1 = false;  ///< without settings: format version 1
};
constexpr Seed kSeeds[] = {{"empty_map", 0, 0, false},
                           {"points_only", 3, 0, false},
                           {"two_keyframes", 3, 2, false},
                           {"images", 2, 1, true},
                           {"version_1", 3, 2, false, true}};

TEST(FuzzReplay, KeyFrameMapSeedsAreTheSampleMaps) {
  const std::string folder = std::string(DSLAM_SOURCE_DIR) + "/test/fuzz/corpus/keyframe_map/";
  const bool write = std::getenv("DSLAM_WRITE_FUZZ_SEEDS") != nullptr;
  for (const Seed& seed : kSeeds) {
    KeyFrameMapFile sample = test::SampleMapFile(seed.points, seed.keyframes, seed.images);
    if (seed.version_1) sample.settings.reset();
    if (write) WriteFileAtomically(folder + seed.name, SerialiseKeyFrameMap(sample), "test");
    const KeyFrameMapFile stored = LoadKeyFrameMap(folder + seed.name);
    test::ExpectSameMap(stored, sample);
    EXPECT_EQ(stored.images.size(), sample.images.size()) << seed.name;
  }
}

TEST(FuzzReplay, KeyFrameMap) { ReplayStoredInputs("keyframe_map", KeyFrameMapHarness); }

// The harness returns on a valid file (checked against its writer) and on a refused one.
TEST(FuzzReplay, KeyFrameMapHarnessAcceptsTheSamples) {
  EXPECT_NO_THROW(KeyFrameMapHarness(SerialiseKeyFrameMap(test::SampleMapFile(3, 2, true))));
  EXPECT_NO_THROW(KeyFrameMapHarness("not a map"));
}

}  // namespace
}  // namespace fuzz
}  // namespace dslam
