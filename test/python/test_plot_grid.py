"""scripts/plot_grid and dslam_tools.grid_files: reading a hand-written grid (map_server's YAML with dslam's keys and its
PGM), the cells a PCD fills in the grid's band (known points: one in the band, one above it, one
outside the grid), and the PNG of both."""

import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

SCRIPTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # nose does not add it
from dslam_tools import grid_files  # noqa: E402
from test_plot_map import write_pcd  # noqa: E402

GRID_YAML = """image: g.pgm
resolution: 0.5
origin: [-1.0, -1.0, 0.0]
negate: 0
occupied_thresh: 0.65
free_thresh: 0.196
mode: trinary
T_world_grid: [0.0, 0.0, -0.5, 0.0, 0.0, 0.0, 1.0]
min_height_m: 0.1
max_height_m: 2.0
floor_from_plane: 1
"""


def load_plot_grid():
    import importlib.machinery
    import importlib.util
    loader = importlib.machinery.SourceFileLoader("plot_grid", os.path.join(SCRIPTS, "plot_grid"))
    spec = importlib.util.spec_from_loader("plot_grid", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


class PlotGridTest(unittest.TestCase):
    def test_grid_unmasked_cells_and_png(self):
        plot_grid = load_plot_grid()
        with tempfile.TemporaryDirectory() as work:
            yaml_path = os.path.join(work, "g.yaml")
            with open(yaml_path, "w") as handle:
                handle.write(GRID_YAML)
            with open(os.path.join(work, "g.pgm"), "wb") as handle:  # 4 x 3 cells
                handle.write(b"P5\n# test\n4 3\n255\n" + bytes([0, 254, 205, 254] * 3))
            keys, cells = grid_files.read_grid(yaml_path)
            self.assertEqual(cells.shape, (3, 4))
            self.assertEqual(list(cells[0]), [0, 254, 205, 254])
            # As the message has them: row j from the lowest y (the PGM's last row), 100 / 0 / -1.
            self.assertEqual(list(grid_files.cells(cells)[0]), [100, 0, -1, 0])
            # The PCD's points (test_plot_map's): (0, 0, 1) and (1, -0.5, 2) and (-1, 0.5, 3) in
            # the world; in the grid frame z + 0.5: heights 1.5 (band), 2.5 and 3.5 (above).
            pcd = os.path.join(work, "u.pcd")
            write_pcd(pcd, "binary")
            filled = plot_grid.unmasked_cells(cells.shape, keys, pcd)
            expected = np.full((3, 4), 205, dtype=np.uint8)
            expected[3 - 1 - 2, 2] = 0  # (0, 0): cell i = 2, j = 2 -> row 0
            np.testing.assert_array_equal(filled, expected)
            self.assertEqual(plot_grid.camera_pixel(cells.shape, keys), (2.0, 0.0))
            out = os.path.join(work, "grid.png")
            subprocess.check_call([sys.executable, os.path.join(SCRIPTS, "plot_grid"), "--grid",
                                   yaml_path, "--unmasked-map", pcd, "--output", out],
                                  stdout=subprocess.DEVNULL)
            with open(out, "rb") as handle:
                self.assertEqual(handle.read(8), b"\x89PNG\r\n\x1a\n")


if __name__ == "__main__":
    unittest.main()
