#include "dslam/tracking/id_set.h"

#include <random>
#include <stdexcept>
#include <unordered_set>

#include <gtest/gtest.h>

namespace dslam {
namespace {

TEST(IdSet, AgreesWithAStandardSetOnRandomIdsWithRepeats) {
  std::mt19937_64 rng(21);
  for (const size_t n : {0u, 1u, 7u, 100u, 5000u}) {
    // Ids from a range about as large as n (many repeats) and from a wide range.
    for (const PointId range : {static_cast<PointId>(n) + 1, PointId{1} << 40}) {
      std::uniform_int_distribution<PointId> draw(0, range);
      IdSet set(n);
      std::unordered_set<PointId> expected;
      for (size_t i = 0; i < n; ++i) {
        const PointId id = draw(rng);
        EXPECT_EQ(set.Insert(id), expected.insert(id).second);
      }
      EXPECT_EQ(set.size(), expected.size());
      for (int probe = 0; probe < 200; ++probe) {
        const PointId id = draw(rng);
        EXPECT_EQ(set.Contains(id), expected.count(id) == 1);
      }
      for (PointId id : expected) EXPECT_TRUE(set.Contains(id));
    }
  }
}

TEST(IdSet, SequentialIdsAndCapacity) {
  IdSet set(3);  // 16 slots: up to 8 elements fit
  for (PointId id = 0; id < 8; ++id) EXPECT_TRUE(set.Insert(id * 16));
  EXPECT_FALSE(set.Insert(32));
  EXPECT_TRUE(set.Contains(112));
  EXPECT_FALSE(set.Contains(1));
  EXPECT_THROW(set.Insert(9), std::length_error);
}

}  // namespace
}  // namespace dslam
