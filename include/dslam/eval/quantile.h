#pragma once
// The one rule of every reported median and quantile (summary JSON, benchmarks, metrics):
// linear interpolation between order statistics, numpy's default (numpy.quantile /
// numpy.percentile, method "linear"). scripts/dslam_tools/stats.py has the same rule in Python.

#include <utility>
#include <vector>

namespace dslam {

/// The `fraction`-quantile of `values` (fraction in [0, 1], clamped to it): with the values
/// sorted ascending, position p = (n - 1) * fraction, the value between sorted[floor(p)] and
/// sorted[floor(p) + 1] at the share p - floor(p), interpolated as numpy does (from the lower
/// value below a share of 0.5, from the upper one from 0.5 on), so the results equal numpy's
/// bit for bit. 0 when `values` is empty.
double Quantile(std::vector<double> values, double fraction);

/// Quantile(values, 0.5): the middle value of an odd count, halfway between the two middle values
/// of an even count; 0 when `values` is empty.
inline double Median(std::vector<double> values) { return Quantile(std::move(values), 0.5); }

}  // namespace dslam
