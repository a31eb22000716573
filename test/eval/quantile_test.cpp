// Tests of the one rule of reported quantiles (quantile.h) against numpy.quantile's values
// (numpy 1.24, method "linear", printed with repr). test/python/test_stats.py checks
// scripts/dslam_tools/stats.py on the same vectors and numbers.
#include <vector>

#include <gtest/gtest.h>

#include "dslam/eval/quantile.h"

namespace dslam {
namespace {

const std::vector<double> kOdd = {5.0, 1.0, 4.0, 2.0, 3.0};
const std::vector<double> kEven = {4.0, 1.0, 3.0, 2.0};
// Frame times [ms] in no order, 20 of them: p95 lies between the two largest.
const std::vector<double> kTimes = {12.31, 9.84,  10.02, 15.7, 11.05, 9.91,  30.4,
                                    10.6,  11.9,  10.33, 9.77, 13.48, 10.15, 12.02,
                                    18.9,  10.88, 11.41, 9.96, 10.47, 14.22};

const std::vector<double> kFractions = {0.0, 0.1, 0.5, 0.95, 1.0};

/// Checks Quantile(values, f) for f in kFractions against `expected` exactly: the same
/// operations as numpy's give the same doubles.
void ExpectQuantiles(const std::vector<double>& values, const std::vector<double>& expected) {
  for (size_t i = 0; i < kFractions.size(); ++i) {
    EXPECT_EQ(Quantile(values, kFractions[i]), expected[i]) << "fraction " << kFractions[i];
  }
}

TEST(Quantile, OddCountEqualsNumpy) {
  ExpectQuantiles(kOdd, {1.0, 1.4, 3.0, 4.8, 5.0});
  EXPECT_EQ(Median(kOdd), 3.0);
}

TEST(Quantile, EvenCountInterpolatesBetweenTheMiddleValues) {
  ExpectQuantiles(kEven, {1.0, 1.3, 2.5, 3.8499999999999996, 4.0});
  EXPECT_EQ(Median(kEven), 2.5);  // the same function: no second rule
}

TEST(Quantile, FrameTimesEqualNumpy) {
  ExpectQuantiles(kTimes, {9.77, 9.903, 10.965, 19.47500000000001, 30.4});
}

TEST(Quantile, OneElementIsEveryQuantile) { ExpectQuantiles({7.0}, {7.0, 7.0, 7.0, 7.0, 7.0}); }

TEST(Quantile, EmptyInputIsZeroAndFractionIsClamped) {
  EXPECT_EQ(Quantile({}, 0.5), 0.0);  // the summary JSON's value when nothing ran
  EXPECT_EQ(Median({}), 0.0);
  EXPECT_EQ(Quantile(kOdd, -0.5), 1.0);
  EXPECT_EQ(Quantile(kOdd, 1.5), 5.0);
}

}  // namespace
}  // namespace dslam
