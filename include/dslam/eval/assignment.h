#pragma once
// Minimum-cost assignment (the Hungarian method, Kuhn 1955 / Munkres 1957, in the O(n^2 m)
// shortest-augmenting-path form with potentials) and its gated form used to match estimated to
// true objects (object_metrics.h).

#include <utility>
#include <vector>

#include <Eigen/Core>

namespace dslam {

/// The assignment of rows to distinct columns that minimises the sum of `cost(row, col)` over the
/// assigned pairs, with min(rows, cols) pairs. Returns, per row, its column or -1 (only when
/// rows > cols). Costs must be finite. An empty matrix gives an empty (or all -1) result.
std::vector<int> MinCostAssignment(const Eigen::MatrixXd& cost);

/// Pairs (row, col) of a one-to-one matching that first has as many pairs with
/// `distance(row, col) <= gate` as possible and, among those, the smallest sum of distances;
/// only pairs within the gate are returned, sorted by row. Distances must be finite and >= 0.
std::vector<std::pair<int, int>> GatedAssignment(const Eigen::MatrixXd& distance, double gate);

}  // namespace dslam
