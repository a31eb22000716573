#include "dslam/place_recognition/bow_vector.h"

#include <algorithm>
#include <cmath>

namespace dslam {
namespace {

double NormL1(const BowVector& v) {
  double sum = 0.0;
  for (const auto& [word, weight] : v) sum += std::abs(weight);
  return sum;
}

}  // namespace

void NormaliseL1(BowVector* v) {
  const double norm = NormL1(*v);
  if (norm <= 0.0) return;
  for (auto& [word, weight] : *v) weight /= norm;
}

double ScoreL1(const BowVector& a, const BowVector& b) {
  const double norm_a = NormL1(a);
  const double norm_b = NormL1(b);
  if (norm_a <= 0.0 || norm_b <= 0.0) return 0.0;
  // Both normalised: |a - b|_1 = 2 - sum over the common words of (|x| + |y| - |x - y|).
  double common = 0.0;
  auto i = a.begin();
  auto j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (i->first < j->first) {
      ++i;
    } else if (j->first < i->first) {
      ++j;
    } else {
      const double x = i->second / norm_a;
      const double y = j->second / norm_b;
      common += std::abs(x) + std::abs(y) - std::abs(x - y);
      ++i;
      ++j;
    }
  }
  return std::clamp(0.5 * common, 0.0, 1.0);
}

}  // namespace dslam
