"""Tests of scripts/accuracy_check.py's pure parts: the seed ranges, the ATE sums per scenario and
the verdict on each criterion of issue 13 (and the segmentation scores of scripts/benchmark.py it
compares), on hand-made numbers. Builds and runs nothing of dslam."""

import os
import sys
import unittest

SCRIPTS = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
import accuracy_check  # noqa: E402
import benchmark  # noqa: E402


def result(ate, precision=None, recall=None, false_dynamic=None):
    """A run's summary and evaluation as benchmark.evaluate returns them: the segmentation keys
    only where the scene is scored, true_dynamic > 0 where it has movers."""
    out = {"ate_rmse_m": ate}
    if false_dynamic is not None:
        out.update(false_dynamic_rate=false_dynamic, true_dynamic=0, missed_dynamic=0)
    if precision is not None:
        out.update(dynamic_precision=precision, dynamic_recall=recall, true_dynamic=10)
    return out


def row(name, scenario, before, after, identical=False):
    return dict(name=name, scenario=scenario, before=before, after=after, identical=identical,
                moving=benchmark.has_movers(before))


def verdict_of(rows):
    """{criterion prefix (its first word after the verdict): (passed, offenders)}."""
    return {criterion.split()[0]: (passed, offenders)
            for criterion, passed, offenders in accuracy_check.verdicts(rows)}


class SeedsTest(unittest.TestCase):
    def test_ranges_and_lists(self):
        self.assertEqual(accuracy_check.parse_seeds("1-5"), [1, 2, 3, 4, 5])
        self.assertEqual(accuracy_check.parse_seeds("1,3"), [1, 3])
        self.assertEqual(accuracy_check.parse_seeds("1-2,5,"), [1, 2, 5])


class VerdictTest(unittest.TestCase):
    def test_identical_runs_pass_and_absent_bonn_is_named(self):
        rows = [row("walking_f300_s1", "walking", result(0.02, 0.8, 0.6, 0.1),
                    result(0.02, 0.8, 0.6, 0.1), identical=True)]
        verdict = verdict_of(rows)
        self.assertEqual([passed for passed, _ in verdict.values()], [True] * 4)
        self.assertEqual(verdict["shared"][1], ["not measured"])
        self.assertIn("- trajectories byte-identical: 1 of 1", accuracy_check.verdict_lines(rows))

    def test_scenario_sum_within_three_percent(self):
        # Sums 0.200 -> 0.204 (+2 %) for walking, 0.200 -> 0.207 (+3.5 %) for slow_box.
        rows = [row("walking_f300_s1", "walking", result(0.1), result(0.104)),
                row("walking_f300_s2", "walking", result(0.1), result(0.1)),
                row("slow_box_f300_s1", "slow_box", result(0.1), result(0.1)),
                row("slow_box_f300_s2", "slow_box", result(0.1), result(0.107))]
        sums = accuracy_check.scenario_sums(rows)
        self.assertAlmostEqual(sums["walking"][1], 0.204)
        self.assertEqual(verdict_of(rows)["sum"], (False, ["slow_box: +3.5 %"]))
        # A better sum by more than 3 % is outside the tolerance too ("within 3 % of before").
        rows[3]["after"] = result(0.093)
        self.assertEqual(verdict_of(rows)["sum"], (False, ["slow_box: -3.5 %"]))

    def test_sequence_worse_by_max_of_1_mm_and_10_percent(self):
        rows = [row("a", "s", result(0.005), result(0.0059)),  # +0.9 mm, 18 %: within 1 mm
                row("b", "s", result(0.050), result(0.0549)),  # +4.9 mm, 9.8 %: within 10 %
                row("c", "s", result(0.050), result(0.0300)),  # better
                row("d", "s", result(0.050), result(0.0552))]  # +5.2 mm, 10.4 %
        self.assertEqual(verdict_of(rows)["no"], (False, ["d: +5.2 mm"]))

    def test_bonn_no_worse_than_2_mm(self):
        bonn = accuracy_check.BONN
        rows = [row(bonn, None, result(0.054), result(0.0559))]  # +1.9 mm
        self.assertEqual(verdict_of(rows)["shared"], (True, []))
        rows = [row(bonn, None, result(0.054), result(0.0561))]  # +2.1 mm, within 10 % though
        verdict = verdict_of(rows)
        self.assertEqual(verdict["shared"], (False, [f"{bonn}: +2.1 mm"]))
        self.assertTrue(verdict["no"][0])
        self.assertEqual(accuracy_check.scenario_sums(rows), {})  # real data has no scenario

    def test_segmentation_within_2_points(self):
        rows = [row("walking_f300_s1", "walking", result(0.02, 0.80, 0.60, 0.100),
                    result(0.02, 0.82, 0.57, 0.119)),  # precision +0.02 ok, recall -0.03
                # No movers: precision and recall are not scored, the static share +0.025 is.
                row("static_room_f300_s1", "static_room", result(0.002, false_dynamic=0.010),
                    result(0.002, false_dynamic=0.035)),
                row(accuracy_check.BONN, None, result(0.054), result(0.054))]  # no truth
        self.assertEqual(verdict_of(rows)["segmentation"],
                         (False, ["walking_f300_s1: dyn. recall -0.030",
                                  "static_room_f300_s1: static wrongly dyn. +0.025"]))

    def test_report_lines_name_the_offenders(self):
        rows = [row("d", "s", result(0.050), result(0.0552))]
        lines = accuracy_check.verdict_lines(rows)
        self.assertIn("- FAIL: no sequence worse by more than max(1 mm, 10 %) (d: +5.2 mm)", lines)
        self.assertEqual(accuracy_check.sequence_table(rows)[2],
                         "| d | 0.05000 | 0.05520 | +5.20 | no | - / - / - | - / - / - |")
        self.assertEqual(accuracy_check.scenario_table(rows)[2],
                         "| s | 0.05000 | 0.05520 | +10.40 |")


class SegmentationTest(unittest.TestCase):
    def test_benchmark_columns(self):
        moving = result(0.02, 0.91234, 0.5, 0.012345)
        self.assertEqual(benchmark.segmentation(moving, True), "0.912 | 0.500 | 0.0123")
        self.assertEqual(benchmark.segmentation(moving, False), "- | - | 0.0123")
        self.assertEqual(benchmark.segmentation(result(0.05), False), "- | - | -")


class LoopColumnsTest(unittest.TestCase):
    def test_loop_columns(self):
        self.assertEqual(benchmark.loops({"loop_closing": False}), "- | -")
        self.assertEqual(benchmark.loops({}), "- | -")
        closed = {"loops": 3, "false_loops": 0, "median_loop_ms": 3.86,
                  "p95_loop_ms": 16.49}
        self.assertEqual(benchmark.loops(closed), "3 / 0 | 3.9 / 16.5")
        # The header has a column for every cell of a row (the row's cells end with these two).
        self.assertEqual(benchmark.HEADER.splitlines()[0].count("|"),
                         benchmark.HEADER.splitlines()[1].count("|"))


if __name__ == "__main__":
    unittest.main()
