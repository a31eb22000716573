"""Tests of scripts/mapping_benchmark.py's pure parts (dslam_tools.mapping_report: the commands of
a run, the numbers from the eval tools' JSON files, the mean over seeds, the tables) and of its
seed parsing, on fake files. Builds and runs nothing of dslam."""

import json
import os
import shutil
import sys
import tempfile
import unittest

SCRIPTS = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
import mapping_benchmark  # noqa: E402
from dslam_tools import mapping_report  # noqa: E402


def eval_objects(found, centroid, velocity, false, switches):
    return {"found_share": found, "centroid_error_median_m": centroid,
            "velocity_error_median_mps": velocity, "false_share": false, "id_switches": switches}


def eval_map(ghost, coverage, grid=None):
    """dslam_eval_map's JSON; `grid`: (ghost cells, unmasked ghost cells, precision, recall)."""
    numbers = {"ghost_share": ghost, "static_coverage": coverage, "map_points": 1000}
    if grid is not None:
        numbers.update(zip(("grid_ghost_cells", "unmasked_grid_ghost_cells", "grid_precision",
                            "grid_recall"), grid))
    return numbers


class MappingReportTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="dslam_mapping_report_")

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def write_run(self, name, objects, masked, unmasked):
        out_dir = os.path.join(self.tmp, name)
        os.makedirs(out_dir)
        paths = mapping_report.run_paths(out_dir)
        for role, content in (("eval_objects", objects), ("eval_map", masked),
                              ("eval_map_unmasked", unmasked)):
            with open(paths[role], "w") as handle:
                json.dump(content, handle)
        return paths

    def test_commands_pass_the_outputs_on(self):
        paths = mapping_report.run_paths("/out")
        run, objects, masked, unmasked = mapping_report.run_commands(
            "/bin", "/data/walking", paths, ["--config", "p.yaml"])
        self.assertEqual(run[0], "/bin/dslam_run_dataset")
        for flag, role in (("--trajectory", "trajectory"), ("--map", "map"),
                           ("--map-unmasked", "map_unmasked"), ("--objects", "objects"),
                           ("--summary", "summary")):
            self.assertEqual(run[run.index(flag) + 1], paths[role])
        self.assertEqual(run[-2:], ["--config", "p.yaml"])
        self.assertEqual(objects[0], "/bin/dslam_eval_objects")
        self.assertEqual(objects[objects.index("--objects") + 1], "/out/objects.txt")
        self.assertEqual(masked[masked.index("--map") + 1], "/out/map.pcd")
        self.assertEqual(run[run.index("--grid") + 1], "/out/grid.yaml")
        self.assertEqual(masked[masked.index("--grid") + 1], "/out/grid.yaml")
        self.assertEqual(masked[masked.index("--unmasked-map") + 1], "/out/map_unmasked.pcd")
        self.assertEqual(unmasked[unmasked.index("--map") + 1], "/out/map_unmasked.pcd")
        self.assertEqual(unmasked[unmasked.index("--json") + 1], "/out/eval_map_unmasked.json")
        for cmd in (objects, masked, unmasked):
            self.assertEqual(cmd[cmd.index("--dataset") + 1], "/data/walking")
            self.assertEqual(cmd[cmd.index("--trajectory") + 1], "/out/trajectory.txt")

    def test_numbers_mean_and_table(self):
        a = mapping_report.load_run(self.write_run(
            "a", eval_objects(0.9, 0.10, 0.20, 0.05, 2), eval_map(0.002, 0.45, (3, 700, 0.9, 1.0)),
            eval_map(0.08, 0.50)))
        b = mapping_report.load_run(self.write_run(
            "b", eval_objects(0.8, 0.14, 0.30, 0.15, 5), eval_map(0.004, 0.40),
            eval_map(0.10, 0.50)))
        self.assertAlmostEqual(a["coverage_ratio"], 0.9)
        self.assertEqual(a["ghost_unmasked"], 0.08)
        mean = mapping_report.mean_numbers([a, b])
        self.assertAlmostEqual(mean["found_share"], 0.85)
        self.assertAlmostEqual(mean["id_switches"], 3.5)
        self.assertAlmostEqual(mean["coverage_ratio"], 0.85)
        text = mapping_report.scenario_table("walking", [1, 2], [a, b])
        lines = text.splitlines()
        self.assertEqual(len(lines), 5)  # heading, rule, two seeds, mean
        self.assertTrue(lines[0].startswith("| run | found share | centroid median [m] |"))
        self.assertEqual(lines[1].count("---"), len(mapping_report.COLUMNS) + 1)
        self.assertEqual(lines[2], "| walking seed 1 | 0.900 | 0.100 | 0.200 | 0.050 | 2.0 | "
                                   "0.0020 | 0.0800 | 0.450 | 0.500 | 0.900 | 3.0 | 700.0 | "
                                   "0.900 | 1.000 |")
        self.assertTrue(lines[4].startswith("| walking mean | 0.850 | 0.120 | 0.250 | 0.100 | "
                                            "3.5 | 0.0030 | 0.0900 |"))

    def test_nothing_to_measure_is_n_a(self):
        # static_room: no truth objects (the tool writes null), an empty unmasked-map coverage.
        run = mapping_report.load_run(self.write_run(
            "s", eval_objects(None, None, None, 0.0, 0), eval_map(0.0, 0.7),
            eval_map(0.0, 0.0)))
        self.assertIsNone(run["found_share"])
        self.assertIsNone(run["coverage_ratio"])
        row = mapping_report.summary_table([("static_room", run)]).splitlines()[2]
        self.assertEqual(row, "| static_room | n/a | n/a | n/a | 0.000 | 0.0 | 0.0000 | 0.0000 | "
                              "0.700 | 0.000 | n/a | n/a | n/a | n/a | n/a |")
        mean = mapping_report.mean_numbers([run, dict(run, found_share=0.5)])
        self.assertEqual(mean["found_share"], 0.5)  # the mean of the runs that have a value

    def test_seeds_separate_or_comma_separated(self):
        self.assertEqual(mapping_benchmark.parse_seeds(["1", "2,3"]), [1, 2, 3])
        args = mapping_benchmark.parse_args(["--seeds", "4", "5", "--scenarios", "walking"])
        self.assertEqual(args.seeds, [4, 5])
        self.assertEqual(args.scenarios, ["walking"])
        self.assertEqual(mapping_benchmark.parse_args([]).seeds, [1, 2, 3])
        self.assertEqual(mapping_benchmark.parse_args([]).scenarios, mapping_report.SCENARIOS)


if __name__ == "__main__":
    unittest.main()
