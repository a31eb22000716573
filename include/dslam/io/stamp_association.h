#pragma once
// Associating two stamp sequences the TUM way: greedy by smallest time difference, each stamp
// used at most once (TUM's associate.py). Shared by dataset reading (colour <-> depth) and
// trajectory evaluation (estimate <-> ground truth).

#include <cstddef>
#include <utility>
#include <vector>

namespace dslam {

/// Pairs (index into `a`, index into `b`) with |a - b| <= max_dt_s [s], chosen greedily by
/// smallest |a - b| (ties: lower index into `a`, then into `b`), each index used at most once;
/// sorted by the stamp of `a`. Neither input needs to be sorted.
std::vector<std::pair<std::size_t, std::size_t>> AssociateStamps(const std::vector<double>& a,
                                                                 const std::vector<double>& b,
                                                                 double max_dt_s);

}  // namespace dslam
