#include "dslam/loop_closing/loop_consistency.h"

#include <algorithm>
#include <utility>

namespace dslam {
namespace {

/// Whether two ascending id lists share an id.
bool Overlap(const std::vector<int>& a, const std::vector<int>& b) {
  auto i = a.begin();
  auto j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (*i == *j) return true;
    *i < *j ? ++i : ++j;
  }
  return false;
}

}  // namespace

std::vector<int> ConsistentGroups::Update(const std::vector<CandidateGroup>& groups, int required) {
  std::vector<Chain> next;
  std::vector<int> consistent;
  for (const CandidateGroup& group : groups) {
    int previous = 0;
    for (const Chain& chain : chains_) {
      if (Overlap(chain.keyframes, group.keyframes)) previous = std::max(previous, chain.length);
    }
    next.push_back({group.keyframes, previous + 1});
    if (previous + 1 >= required) consistent.push_back(group.candidate);
  }
  chains_ = std::move(next);
  return consistent;
}

}  // namespace dslam
