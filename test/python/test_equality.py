"""Tests of scripts/dslam_tools/equality.py (the status CSV and summary JSON comparison of
scripts/equality_check.sh) on hand-written files: timing values are ignored, anything else that
differs is reported, quantile keys are counted apart. Builds and runs nothing of dslam."""
import json
import os
import sys
import tempfile
import unittest

SCRIPTS = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
from dslam_tools import equality  # noqa: E402


class Equality(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp()

    def write(self, name, text):
        path = os.path.join(self.folder, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_csv_ignores_timing_columns_only(self):
        a = self.write("a.csv", "frame,tracked,total_ms\n0,10,5.1\n1,12,4.0\n")
        b = self.write("b.csv", "frame,tracked,total_ms\n0,10,6.3\n1,12,3.9\n")
        c = self.write("c.csv", "frame,tracked,total_ms\n0,10,5.1\n1,13,4.0\n")
        self.assertEqual(equality.compare_csv(a, b), [])
        self.assertEqual(equality.compare_csv(a, c), ["row 2 tracked: 12 -> 13"])

    def test_csv_column_order_and_rows_count(self):
        a = self.write("a.csv", "frame,tracked\n0,10\n")
        b = self.write("b.csv", "tracked,frame\n10,0\n")
        c = self.write("c.csv", "frame,tracked\n0,10\n1,11\n")
        self.assertTrue(equality.compare_csv(a, b)[0].startswith("columns differ"))
        self.assertEqual(equality.compare_csv(a, c), ["1 rows against 2"])

    def test_json_keys_values_and_quantiles(self):
        a = self.write("a.json", json.dumps({"frames": 3, "median_tracking_ms": 1.0,
                                             "median_graph_points": 10}))
        b = self.write("b.json", json.dumps({"frames": 3, "median_tracking_ms": 2.0,
                                             "median_graph_points": 10.5}))
        c = self.write("c.json", json.dumps({"median_tracking_ms": 1.0, "frames": 3,
                                             "median_graph_points": 10}))
        d = self.write("d.json", json.dumps({"frames": 4, "median_tracking_ms": 1.0,
                                             "median_graph_points": 10}))
        self.assertEqual(equality.compare_json(a, b),
                         ([], ["median_graph_points: 10 -> 10.5"]))
        self.assertTrue(equality.compare_json(a, c)[0][0].startswith("keys differ"))
        self.assertEqual(equality.compare_json(a, d), (["frames: 3 -> 4"], []))


if __name__ == "__main__":
    unittest.main()
