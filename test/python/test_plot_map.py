"""scripts/dslam_tools/pcd.py (the PCD reader of plot_map) on hand-written ascii and binary files
with known points and colours, and plot_map rendering two of them to a PNG."""

import os
import struct
import subprocess
import sys
import tempfile
import unittest

SCRIPTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
from dslam_tools.pcd import read_pcd  # noqa: E402

POINTS = [(0.0, 0.0, 1.0, 0xFF0000), (1.0, -0.5, 2.0, 0x00FF00), (-1.0, 0.5, 3.0, 0x0000FF)]


def write_pcd(path, data):
    header = ("# .PCD v0.7\nVERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\n"
              f"COUNT 1 1 1 1\nWIDTH {len(POINTS)}\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\n"
              f"POINTS {len(POINTS)}\nDATA {data}\n")
    with open(path, "wb") as handle:
        handle.write(header.encode("ascii"))
        for x, y, z, rgb in POINTS:
            if data == "binary":
                handle.write(struct.pack("<fffI", x, y, z, rgb))
            else:
                packed = struct.unpack("<f", struct.pack("<I", rgb))[0]
                handle.write(f"{x} {y} {z} {packed!r}\n".encode("ascii"))


class PcdTest(unittest.TestCase):
    def check(self, data):
        with tempfile.TemporaryDirectory() as work:
            path = os.path.join(work, "map.pcd")
            write_pcd(path, data)
            xyz, colours = read_pcd(path)
            self.assertEqual(xyz.shape, (3, 3))
            self.assertAlmostEqual(xyz[1][0], 1.0)
            self.assertAlmostEqual(xyz[2][2], 3.0)
            self.assertEqual(list(colours[0]), [1.0, 0.0, 0.0])
            self.assertEqual(list(colours[1]), [0.0, 1.0, 0.0])
            self.assertEqual(list(colours[2]), [0.0, 0.0, 1.0])

    def test_binary(self):
        self.check("binary")

    def test_ascii(self):
        self.check("ascii")

    def test_plot_map_writes_a_png(self):
        with tempfile.TemporaryDirectory() as work:
            a, b = os.path.join(work, "a.pcd"), os.path.join(work, "b.pcd")
            write_pcd(a, "binary")
            write_pcd(b, "ascii")
            out = os.path.join(work, "maps.png")
            subprocess.check_call([sys.executable, os.path.join(SCRIPTS, "plot_map"), "--map", a,
                                   "--title", "A", "--map", b, "--output", out],
                                  stdout=subprocess.DEVNULL)
            with open(out, "rb") as handle:
                self.assertEqual(handle.read(8), b"\x89PNG\r\n\x1a\n")


if __name__ == "__main__":
    unittest.main()
