"""The one rule of every reported median and quantile of the scripts: linear interpolation between
order statistics, numpy's default (numpy.quantile / numpy.percentile, method "linear"), the rule
of dslam::Quantile (include/dslam/eval/quantile.h) that the summary JSON's median_* and p95_*
keys use. Pure Python: the scripts run without numpy."""

import math

NAN = float("nan")  # the `empty` value of the tools whose tables and JSON write nan for no values


def quantile(values, fraction, empty=None):
    """The `fraction`-quantile of `values` (fraction in [0, 1], clamped to it): with the values
    sorted, position p = (n - 1) * fraction, the value between sorted[floor(p)] and
    sorted[floor(p) + 1] at the share p - floor(p), interpolated as numpy does (from the lower
    value below a share of 0.5, from the upper one from 0.5 on), so the results equal numpy's and
    dslam::Quantile's bit for bit. `empty` when `values` is empty (dslam::Quantile gives 0)."""
    if not values:
        return empty
    ordered = sorted(float(v) for v in values)
    last = len(ordered) - 1
    position = last * min(max(float(fraction), 0.0), 1.0)
    below = min(int(math.floor(position)), last)
    share = position - below
    low = ordered[below]
    if below == last:
        return low
    high = ordered[below + 1]
    step = high - low
    return low + step * share if share < 0.5 else high - step * (1.0 - share)


def median(values, empty=None):
    """quantile(values, 0.5, empty): the middle value of an odd count, halfway between the two
    middle values of an even count."""
    return quantile(values, 0.5, empty)
