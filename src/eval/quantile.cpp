// Reported quantiles by linear interpolation between order statistics (quantile.h).
#include "dslam/eval/quantile.h"

#include <algorithm>
#include <cmath>

namespace dslam {

double Quantile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  const size_t last = values.size() - 1;
  const double position = static_cast<double>(last) * std::clamp(fraction, 0.0, 1.0);
  const size_t below = std::min(static_cast<size_t>(std::floor(position)), last);
  const double share = position - static_cast<double>(below);
  std::nth_element(values.begin(), values.begin() + below, values.end());
  const double low = values[below];
  if (below == last) return low;
  // The next order statistic: the smallest of the values after the nth_element partition.
  const double high = *std::min_element(values.begin() + below + 1, values.end());
  const double step = high - low;
  // numpy's _lerp: exact at both ends of the interval.
  return share < 0.5 ? low + step * share : high - step * (1.0 - share);
}

}  // namespace dslam
