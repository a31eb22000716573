// Tests of the minimum-cost assignment against hand-made cases and brute force.
#include <algorithm>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "dslam/eval/assignment.h"

namespace dslam {
namespace {

double CostOf(const Eigen::MatrixXd& cost, const std::vector<int>& col_of_row) {
  double total = 0.0;
  for (size_t r = 0; r < col_of_row.size(); ++r) {
    if (col_of_row[r] >= 0) total += cost(r, col_of_row[r]);
  }
  return total;
}

/// The smallest total cost over all assignments of min(rows, cols) pairs, by enumeration.
double BruteForceMinimum(const Eigen::MatrixXd& cost) {
  const bool transpose = cost.rows() > cost.cols();
  const Eigen::MatrixXd a = transpose ? Eigen::MatrixXd(cost.transpose()) : cost;
  std::vector<int> cols(a.cols());
  std::iota(cols.begin(), cols.end(), 0);
  double best = 1e300;
  do {  // every ordering of the columns; the first a.rows() of them go to the rows
    double total = 0.0;
    for (int r = 0; r < a.rows(); ++r) total += a(r, cols[r]);
    best = std::min(best, total);
  } while (std::next_permutation(cols.begin(), cols.end()));
  return best;
}

TEST(Assignment, BeatsGreedyOnACrossing) {
  // Greedy takes (0,0) = 1 and is left with (1,1) = 100; the optimum crosses: 2 + 2.
  Eigen::MatrixXd cost(2, 2);
  cost << 1, 2, 2, 100;
  EXPECT_EQ(MinCostAssignment(cost), (std::vector<int>{1, 0}));
}

TEST(Assignment, MatchesBruteForceOnRandomMatrices) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> value(0.0, 10.0);
  for (const auto& [rows, cols] : std::vector<std::pair<int, int>>{
           {1, 1}, {1, 4}, {4, 1}, {3, 3}, {3, 5}, {5, 3}, {6, 6}, {7, 5}}) {
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::MatrixXd cost(rows, cols);
      for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) cost(r, c) = value(rng);
      }
      if (trial % 4 == 0) cost = cost.array().round();  // ties
      const std::vector<int> result = MinCostAssignment(cost);
      ASSERT_EQ(result.size(), static_cast<size_t>(rows));
      std::vector<int> used;
      for (int c : result) {
        if (c >= 0) used.push_back(c);
      }
      ASSERT_EQ(used.size(), static_cast<size_t>(std::min(rows, cols)));
      std::sort(used.begin(), used.end());
      EXPECT_EQ(std::unique(used.begin(), used.end()), used.end()) << "a column used twice";
      EXPECT_NEAR(CostOf(cost, result), BruteForceMinimum(cost), 1e-9)
          << rows << "x" << cols << " trial " << trial;
    }
  }
}

TEST(Assignment, EmptyMatrices) {
  EXPECT_TRUE(MinCostAssignment(Eigen::MatrixXd(0, 3)).empty());
  EXPECT_EQ(MinCostAssignment(Eigen::MatrixXd(2, 0)), (std::vector<int>{-1, -1}));
  EXPECT_TRUE(GatedAssignment(Eigen::MatrixXd(0, 0), 0.5).empty());
}

TEST(GatedAssignment, MorePairsInsideTheGateBeforeASmallerSum) {
  // Inside the gate 0.5: (0,0), (0,1), (1,0). The smallest sum alone would take (0,0) = 0.1 and
  // leave row 1 outside; two pairs (0,1) + (1,0) = 0.5 come first.
  Eigen::MatrixXd distance(2, 2);
  distance << 0.1, 0.3, 0.2, 0.9;
  EXPECT_EQ(GatedAssignment(distance, 0.5), (std::vector<std::pair<int, int>>{{0, 1}, {1, 0}}));
}

TEST(GatedAssignment, DropsPairsOutsideTheGate) {
  Eigen::MatrixXd distance(2, 3);
  distance << 0.7, 0.6, 0.8,  // row 0: nothing within 0.5
      0.4, 0.2, 3.0;
  EXPECT_EQ(GatedAssignment(distance, 0.5), (std::vector<std::pair<int, int>>{{1, 1}}));
  EXPECT_EQ(GatedAssignment(distance, 0.65),
            (std::vector<std::pair<int, int>>{{0, 1}, {1, 0}}));  // two pairs: row 0 takes column 1
}

}  // namespace
}  // namespace dslam
