// Minimum-cost assignment (assignment.h).
#include "dslam/eval/assignment.h"

#include <algorithm>
#include <limits>

namespace dslam {
namespace {

/// Hungarian method for rows <= cols: potentials u (rows) and v (columns), shortest augmenting
/// paths from each new row (1-based arrays, column 0 is the virtual start).
std::vector<int> AssignRowsToColumns(const Eigen::MatrixXd& a) {
  const int n = static_cast<int>(a.rows()), m = static_cast<int>(a.cols());
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(n + 1, 0.0), v(m + 1, 0.0);
  std::vector<int> row_of_col(m + 1, 0), way(m + 1, 0);
  for (int i = 1; i <= n; ++i) {
    row_of_col[0] = i;
    int j0 = 0;
    std::vector<double> min_slack(m + 1, inf);
    std::vector<bool> used(m + 1, false);
    do {
      used[j0] = true;
      const int i0 = row_of_col[j0];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= m; ++j) {
        if (used[j]) continue;
        const double slack = a(i0 - 1, j - 1) - u[i0] - v[j];
        if (slack < min_slack[j]) {
          min_slack[j] = slack;
          way[j] = j0;
        }
        if (min_slack[j] < delta) {
          delta = min_slack[j];
          j1 = j;
        }
      }
      for (int j = 0; j <= m; ++j) {
        if (used[j]) {
          u[row_of_col[j]] += delta;
          v[j] -= delta;
        } else {
          min_slack[j] -= delta;
        }
      }
      j0 = j1;
    } while (row_of_col[j0] != 0);
    do {  // augment along the path back to the virtual column
      const int j1 = way[j0];
      row_of_col[j0] = row_of_col[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> col_of_row(n, -1);
  for (int j = 1; j <= m; ++j) {
    if (row_of_col[j] > 0) col_of_row[row_of_col[j] - 1] = j - 1;
  }
  return col_of_row;
}

}  // namespace

std::vector<int> MinCostAssignment(const Eigen::MatrixXd& cost) {
  if (cost.rows() == 0 || cost.cols() == 0) return std::vector<int>(cost.rows(), -1);
  if (cost.rows() <= cost.cols()) return AssignRowsToColumns(cost);
  const std::vector<int> row_of_col = AssignRowsToColumns(cost.transpose());
  std::vector<int> col_of_row(cost.rows(), -1);
  for (size_t col = 0; col < row_of_col.size(); ++col) col_of_row[row_of_col[col]] = col;
  return col_of_row;
}

std::vector<std::pair<int, int>> GatedAssignment(const Eigen::MatrixXd& distance, double gate) {
  // A pair outside the gate costs more than any set of pairs inside it, so the minimum first
  // maximises the number of pairs inside the gate.
  const double pairs = static_cast<double>(std::min(distance.rows(), distance.cols()));
  const double outside = (pairs + 1.0) * (std::max(gate, 0.0) + 1.0);
  const Eigen::MatrixXd cost = (distance.array() <= gate).select(distance, outside);
  const std::vector<int> col_of_row = MinCostAssignment(cost);
  std::vector<std::pair<int, int>> matched;
  for (size_t row = 0; row < col_of_row.size(); ++row) {
    const int col = col_of_row[row];
    if (col >= 0 && distance(row, col) <= gate) matched.emplace_back(static_cast<int>(row), col);
  }
  return matched;
}

}  // namespace dslam
