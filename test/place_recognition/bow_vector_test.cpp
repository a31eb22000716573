#include "dslam/place_recognition/bow_vector.h"

#include <gtest/gtest.h>

namespace dslam {
namespace {

TEST(BowVectorTest, NormaliseL1MakesTheWeightsSumToOne) {
  BowVector v{{1, 2.0}, {5, 6.0}};
  NormaliseL1(&v);
  EXPECT_DOUBLE_EQ(v[1], 0.25);
  EXPECT_DOUBLE_EQ(v[5], 0.75);
  BowVector empty;
  NormaliseL1(&empty);
  EXPECT_TRUE(empty.empty());
}

TEST(BowVectorTest, ScoreL1IsOneForTheSameDirectionAndZeroWithoutCommonWords) {
  const BowVector a{{1, 1.0}, {2, 3.0}};
  const BowVector twice_a{{1, 2.0}, {2, 6.0}};
  EXPECT_DOUBLE_EQ(ScoreL1(a, twice_a), 1.0);
  EXPECT_DOUBLE_EQ(ScoreL1(a, BowVector{{3, 1.0}}), 0.0);
  EXPECT_DOUBLE_EQ(ScoreL1(a, BowVector{}), 0.0);
}

TEST(BowVectorTest, ScoreL1MatchesTheDefinition) {
  // a = (0.25, 0.75, 0) and b = (0.5, 0, 0.5): |a - b|_1 = 0.25 + 0.75 + 0.5 = 1.5.
  const BowVector a{{1, 1.0}, {2, 3.0}};
  const BowVector b{{1, 1.0}, {7, 1.0}};
  EXPECT_NEAR(ScoreL1(a, b), 1.0 - 0.5 * 1.5, 1e-15);
  EXPECT_NEAR(ScoreL1(b, a), ScoreL1(a, b), 1e-15);
}

}  // namespace
}  // namespace dslam
