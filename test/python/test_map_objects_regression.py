"""Regression test of what dslam builds beside the pose, on a short synthetic `walking` scene
(seed 1, 90 frames) with the existing metrics against dslam_synth's truth: the static map's ghost
share and coverage and the occupancy grid's ghost cells, precision and recall (dslam_eval_map),
and the moving objects' detection and accuracy (dslam_eval_objects). Synchronous runs are deterministic: each bound is about twice the value
measured on these frames (written beside it), so a 2x regression fails."""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # nose does not add it
from test_run_dataset import find_tool  # noqa: E402

FRAMES = 90


class MapAndObjectsRegressionTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="dslam_map_objects_")
        cls.folder = os.path.join(cls.tmp, "walking")
        subprocess.run([find_tool("dslam_synth"), "--scenario", "walking", "--frames",
                        str(FRAMES), "--seed", "1", "--output", cls.folder], check=True,
                       stdout=subprocess.DEVNULL)
        cls.out = os.path.join(cls.tmp, "run")
        subprocess.run([find_tool("dslam_run_dataset"), "--dataset", cls.folder, "--trajectory",
                        cls.out + ".txt", "--map", cls.out + ".pcd", "--map-unmasked",
                        cls.out + "_unmasked.pcd", "--grid", cls.out + "_grid.yaml", "--objects",
                        cls.out + "_objects.txt", "--quiet"], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def evaluate(self, tool, *options):
        path = os.path.join(self.tmp, tool + ".json")
        subprocess.run([find_tool(tool), "--dataset", self.folder, "--trajectory",
                        self.out + ".txt", "--json", path] + list(options), check=True,
                       stdout=subprocess.DEVNULL)
        with open(path) as handle:
            numbers = json.load(handle)
        print("%s: %s" % (tool, numbers))
        return numbers

    def test_static_map_has_no_ghosts_and_covers_the_room(self):
        m = self.evaluate("dslam_eval_map", "--map", self.out + ".pcd")
        self.assertGreater(m["map_points"], 0)
        self.assertLess(m["ghost_share"], GHOST_SHARE_MAX)
        self.assertGreater(m["static_coverage"], STATIC_COVERAGE_MIN)
        self.assertGreater(m["static_share"], STATIC_SHARE_MIN)

    def test_grid_keeps_few_ghost_cells_and_finds_the_static_cells(self):
        g = self.evaluate("dslam_eval_map", "--grid", self.out + "_grid.yaml", "--unmasked-map",
                          self.out + "_unmasked.pcd")
        self.assertLess(g["grid_ghost_cells"], GRID_GHOST_CELLS_MAX)
        self.assertGreater(g["grid_precision"], GRID_PRECISION_MIN)
        self.assertGreater(g["grid_recall"], GRID_RECALL_MIN)
        # The metric sees ghosts where they are: the unmasked map's cells on the people's paths.
        self.assertGreater(g["unmasked_grid_ghost_cells"], UNMASKED_GHOST_CELLS_MIN)

    def test_moving_objects_are_found_where_they_are(self):
        o = self.evaluate("dslam_eval_objects", "--objects", self.out + "_objects.txt")
        self.assertGreater(o["found_share"], FOUND_SHARE_MIN)
        self.assertLess(o["centroid_error_median_m"], CENTROID_ERROR_MAX_M)
        self.assertLess(o["velocity_error_median_mps"], VELOCITY_ERROR_MAX_MPS)
        self.assertLess(o["false_share"], FALSE_SHARE_MAX)
        self.assertGreater(o["mota"], MOTA_MIN)


# Measured at e841b8d (walking, seed 1, 90 frames, defaults), and the bound: twice the share
# missed or wrong, or twice the error.
GHOST_SHARE_MAX = 0.018         # 0.0090 (210 of 23331 map points)
STATIC_COVERAGE_MIN = 0.9925    # 0.9963 (0.0037 of the static surface not covered)
STATIC_SHARE_MIN = 0.684        # 0.8419
# The grid's bounds measured after the views' votes (VoteByViews), 2026-12-05; before them, at
# c487a68: 61 ghost cells, precision 0.8918, recall 1.0000.
GRID_GHOST_CELLS_MAX = 34       # 17 (of 921 cells where only people stood)
GRID_PRECISION_MIN = 0.869      # 0.9348 (occupied cells within a cell of the static truth)
GRID_RECALL_MIN = 0.92          # 0.9604
UNMASKED_GHOST_CELLS_MIN = 354  # 708: the same band of the map without masks and free-space check
FOUND_SHARE_MIN = 0.887         # 0.9435 (167 of 177 truth object-frames)
CENTROID_ERROR_MAX_M = 0.127    # 0.0632 m
VELOCITY_ERROR_MAX_MPS = 0.17   # 0.0846 m/s
FALSE_SHARE_MAX = 0.092         # 0.0457
MOTA_MIN = 0.796                # 0.898

if __name__ == "__main__":
    unittest.main()
