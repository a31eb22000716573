"""Tests of scripts/dslam_tools/stats.py, the scripts' one quantile rule, on the vectors and numbers
of test/eval/quantile_test.cpp (dslam::Quantile): numpy.quantile's values (numpy 1.24, method
"linear", printed with repr), so both languages are held to the same doubles. Builds and runs
nothing of dslam."""

import math
import os
import sys
import unittest

SCRIPTS = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
from dslam_tools import stats  # noqa: E402

ODD = [5.0, 1.0, 4.0, 2.0, 3.0]
EVEN = [4.0, 1.0, 3.0, 2.0]
# Frame times [ms] in no order, 20 of them: p95 lies between the two largest.
TIMES = [12.31, 9.84, 10.02, 15.7, 11.05, 9.91, 30.4, 10.6, 11.9, 10.33, 9.77, 13.48, 10.15,
         12.02, 18.9, 10.88, 11.41, 9.96, 10.47, 14.22]
FRACTIONS = [0.0, 0.1, 0.5, 0.95, 1.0]
# The quantiles at FRACTIONS, as in quantile_test.cpp.
EXPECTED = [
    (ODD, [1.0, 1.4, 3.0, 4.8, 5.0]),
    (EVEN, [1.0, 1.3, 2.5, 3.8499999999999996, 4.0]),
    (TIMES, [9.77, 9.903, 10.965, 19.47500000000001, 30.4]),
    ([7.0], [7.0] * 5),
]


class QuantileTest(unittest.TestCase):
    def test_known_values_bit_for_bit(self):
        for values, expected in EXPECTED:
            got = [stats.quantile(values, f) for f in FRACTIONS]
            self.assertEqual(got, expected, values)

    def test_median_is_the_half_quantile(self):
        self.assertEqual(stats.median(ODD), 3.0)
        self.assertEqual(stats.median(EVEN), 2.5)  # halfway between the middle two
        self.assertEqual(stats.median(TIMES), 10.965)

    def test_empty_input_gives_the_callers_value(self):
        self.assertIsNone(stats.quantile([], 0.5))
        self.assertEqual(stats.median([], 0.0), 0.0)  # dslam::Quantile's convention
        self.assertTrue(math.isnan(stats.quantile([], 0.95, stats.NAN)))

    def test_fraction_is_clamped_and_input_left_unsorted(self):
        values = list(ODD)
        self.assertEqual(stats.quantile(values, -0.5), 1.0)
        self.assertEqual(stats.quantile(values, 1.5), 5.0)
        self.assertEqual(values, ODD)

    def test_numpy_agrees_where_installed(self):
        try:
            import numpy
        except ImportError:
            self.skipTest("numpy not installed")
        for values, _ in EXPECTED:
            for f in FRACTIONS:
                self.assertEqual(stats.quantile(values, f), float(numpy.quantile(values, f)))


if __name__ == "__main__":
    unittest.main()
