// The chains of candidate groups over consecutive query keyframes, with known overlaps.
#include "dslam/loop_closing/loop_consistency.h"

#include <gtest/gtest.h>

namespace dslam {
namespace {

TEST(ConsistentGroups, ChainGrowsWhileGroupsOverlap) {
  ConsistentGroups groups;
  EXPECT_TRUE(groups.Update({{1, {0, 1, 2}}, {9, {8, 9}}}, 3).empty());
  EXPECT_EQ(groups.size(), 2u);
  EXPECT_TRUE(groups.Update({{2, {1, 2, 3}}}, 3).empty());  // 2 in a row
  EXPECT_EQ(groups.Update({{3, {3, 4}}, {20, {20}}}, 3), std::vector<int>({3}));
  EXPECT_EQ(groups.Update({{4, {4, 5}}}, 3), std::vector<int>({4}));  // 4 in a row
}

TEST(ConsistentGroups, AQueryWithoutCandidatesEndsTheChains) {
  ConsistentGroups groups;
  groups.Update({{1, {0, 1}}}, 2);
  groups.Update({}, 2);
  EXPECT_EQ(groups.size(), 0u);
  EXPECT_TRUE(groups.Update({{1, {0, 1}}}, 2).empty());
  EXPECT_EQ(groups.Update({{1, {1}}}, 2), std::vector<int>({1}));
  groups.Clear();
  EXPECT_TRUE(groups.Update({{1, {1}}}, 2).empty());
}

TEST(ConsistentGroups, OneKeyFrameIsEnoughWhenOneIsRequired) {
  ConsistentGroups groups;
  EXPECT_EQ(groups.Update({{5, {5}}, {7, {7}}}, 1), std::vector<int>({5, 7}));
}

}  // namespace
}  // namespace dslam
