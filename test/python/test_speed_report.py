"""Tests of the pure parts of scripts/speed_benchmark.py (dslam_tools.speed_report: the numbers
of one run, the median over rounds, the table, the peak memory of a child) and of its choice of
the reference's catkin target. Builds and runs nothing of dslam. Its quantile rule:
test_stats.py."""

import os
import shutil
import sys
import tempfile
import unittest

SCRIPTS = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
import speed_benchmark  # noqa: E402
from dslam_tools import speed_report  # noqa: E402


def status_row(frame, keyframe, ba_ms=0.0, spd_ms=0.0):
    """The status CSV columns speed_report reads, as csv.DictReader gives them (strings)."""
    return {"frame": str(frame), "keyframe": "1" if keyframe else "0", "ba_ms": f"{ba_ms:.3f}",
            "spd_ms": f"{spd_ms:.3f}"}


class RunMetricsTest(unittest.TestCase):
    def test_current_run(self):
        # Keyframes at frames 0, 3, 9 and 10; runs delivered at frames 2, 5 and 11.
        rows = [status_row(i, i in (0, 3, 9, 10)) for i in range(12)]
        rows[2] = status_row(2, False, ba_ms=10.0, spd_ms=2.0)
        rows[5] = status_row(5, False, ba_ms=20.0, spd_ms=4.0)
        rows[11] = status_row(11, False, ba_ms=5.0, spd_ms=1.0)
        summary = {"median_tracking_ms": 8.0, "p95_tracking_ms": 10.0, "backend_runs": 4,
                   "max_backlog": 1, "frames_with_pose": 12, "frames": 12}
        metrics = speed_report.current_metrics(summary, rows, 30.0)
        self.assertAlmostEqual(metrics["p95_over_median"], 1.25)
        self.assertAlmostEqual(metrics["backend_p95_ms"], 22.8)  # of 6, 12, 24: 24 - 0.1 * 12
        self.assertEqual(metrics["keyframes"], 4)
        self.assertEqual(metrics["backend_runs"], 4)  # the summary's (one run not in the CSV)
        # Intervals 3, 6 and 1 frames at 30 Hz: 100, 200, 33.3 ms; their median 100 ms.
        self.assertAlmostEqual(metrics["keyframe_interval_ms"], 100.0)
        self.assertEqual(metrics["max_backlog"], 1)

    def test_reference_run_tracking_is_its_total(self):
        summary = {"median_total_ms": 14.5, "frames_with_pose": 290, "frames": 300}
        self.assertEqual(speed_report.reference_metrics(summary)["tracking_ms"], 14.5)


class CombineRoundsTest(unittest.TestCase):
    def test_median_of_medians_and_worst_case(self):
        rounds = [{"tracking_ms": 9.0, "max_backlog": 1, "peak_rss_mib": 100.0, "ate_m": None},
                  {"tracking_ms": 7.0, "max_backlog": 3, "peak_rss_mib": 120.0, "ate_m": None},
                  {"tracking_ms": 8.0, "max_backlog": 2, "peak_rss_mib": 90.0, "ate_m": None}]
        combined = speed_report.combine_rounds(rounds)
        self.assertEqual(combined["tracking_ms"], 8.0)
        self.assertEqual(combined["max_backlog"], 3)
        self.assertEqual(combined["peak_rss_mib"], 120.0)
        self.assertIsNone(combined["ate_m"])

    def test_even_round_count_averages_the_middle_pair(self):
        combined = speed_report.combine_rounds([{"tracking_ms": 10.0}, {"tracking_ms": 13.0}])
        self.assertEqual(combined["tracking_ms"], 11.5)


class TableTest(unittest.TestCase):
    def test_row_matches_header_and_shows_ratios(self):
        header = speed_report.table_header("cdfc860")
        self.assertIn("cdfc860 median total [ms]", header)
        current = {"tracking_ms": 6.0, "p95_over_median": 1.4, "backend_p95_ms": 40.26,
                   "keyframe_interval_ms": 333.3, "backend_runs": 9, "keyframes": 9,
                   "max_backlog": 1, "peak_rss_mib": 140.0, "ate_m": 0.0511}
        reference = {"tracking_ms": 13.6, "peak_rss_mib": 95.5, "ate_m": 0.0545}
        row = speed_report.table_row("bonn", current, reference)
        self.assertEqual(row.count("|"), header.splitlines()[0].count("|"))
        self.assertEqual(header.splitlines()[1].count("---"), row.count("|") - 1)
        self.assertEqual(row, "| bonn | 13.6 | 6.0 | 0.44 | 1.40 | 40.3 | 333.3 | 9 / 9 | 1 | "
                              "140.0 / 95.5 | 0.0511 / 0.0545 |")

    def test_missing_numbers_are_not_available(self):
        row = speed_report.table_row("walking", {"tracking_ms": 5.0}, {"tracking_ms": 0.0})
        self.assertEqual(row.split(" | ")[3], "n/a")  # no ratio over a zero reference
        self.assertIn("n/a / n/a", row)


class PeakMemoryTest(unittest.TestCase):
    def test_child_peak_rss_and_exit_code(self):
        tmp = tempfile.mkdtemp(prefix="speed_report_")
        try:
            # The child fills 64 MiB (every page written) and exits with 3.
            code, peak_mib, wall_s = speed_report.run_measured(
                [sys.executable, "-c", "import sys; b = bytearray(64 << 20); sys.exit(3)"],
                os.path.join(tmp, "child.log"))
        finally:
            shutil.rmtree(tmp)
        self.assertEqual(code, 3)
        self.assertGreaterEqual(peak_mib, 64.0)
        self.assertLess(peak_mib, 64.0 + 200.0)  # the interpreter adds tens of MiB, not more
        self.assertGreater(wall_s, 0.0)

    def test_kib_to_mib(self):
        self.assertEqual(speed_report.kib_to_mib(153600), 150.0)


class ReferenceTargetTest(unittest.TestCase):
    def test_old_and_new_target_names(self):
        tmp = tempfile.mkdtemp(prefix="speed_target_")
        try:
            os.makedirs(os.path.join(tmp, "old", "cmake"))
            with open(os.path.join(tmp, "old", "cmake", "odometry.cmake"), "w") as handle:
                handle.write("add_executable(dslam_run_dataset ${X}/run_dataset_main.cpp)\n")
            os.makedirs(os.path.join(tmp, "new", "src", "tools"))
            with open(os.path.join(tmp, "new", "src", "tools", "CMakeLists.txt"), "w") as handle:
                handle.write("dslam_tool(dslam_run_dataset SOURCES run_dataset_main.cpp)\n")
            self.assertEqual(speed_benchmark.tool_target(os.path.join(tmp, "old"),
                                                         "dslam_run_dataset"), "dslam_run_dataset")
            self.assertEqual(speed_benchmark.tool_target(os.path.join(tmp, "new"),
                                                         "dslam_run_dataset"),
                             "dslam_run_dataset_main")
        finally:
            shutil.rmtree(tmp)


if __name__ == "__main__":
    unittest.main()
