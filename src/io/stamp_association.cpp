#include "dslam/io/stamp_association.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace dslam {

std::vector<std::pair<size_t, size_t>> AssociateStamps(const std::vector<double>& a,
                                                       const std::vector<double>& b,
                                                       double max_dt_s) {
  struct Candidate {
    double abs_dt_s;
    size_t a_index, b_index;
  };
  std::vector<std::pair<double, size_t>> b_sorted;
  b_sorted.reserve(b.size());
  for (size_t j = 0; j < b.size(); ++j) b_sorted.emplace_back(b[j], j);
  std::sort(b_sorted.begin(), b_sorted.end());
  std::vector<Candidate> candidates;
  for (size_t i = 0; i < a.size(); ++i) {
    auto it = std::lower_bound(b_sorted.begin(), b_sorted.end(),
                               std::make_pair(a[i] - max_dt_s, size_t{0}));
    for (; it != b_sorted.end() && it->first <= a[i] + max_dt_s; ++it) {
      const double abs_dt = std::abs(it->first - a[i]);
      if (abs_dt <= max_dt_s) candidates.push_back({abs_dt, i, it->second});
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    return std::tie(x.abs_dt_s, x.a_index, x.b_index) < std::tie(y.abs_dt_s, y.a_index, y.b_index);
  });
  std::vector<bool> a_used(a.size(), false), b_used(b.size(), false);
  std::vector<std::pair<size_t, size_t>> pairs;
  for (const Candidate& c : candidates) {
    if (a_used[c.a_index] || b_used[c.b_index]) continue;
    a_used[c.a_index] = b_used[c.b_index] = true;
    pairs.emplace_back(c.a_index, c.b_index);
  }
  std::stable_sort(pairs.begin(), pairs.end(),
                   [&](const auto& x, const auto& y) { return a[x.first] < a[y.first]; });
  return pairs;
}

}  // namespace dslam
