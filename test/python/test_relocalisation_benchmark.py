"""Tests of scripts/relocalisation_benchmark.py's pure parts: the --drop ranges and the dataset
copy that leaves frames out or blanks them, on a hand-written folder. Builds and runs nothing of
dslam."""

import os
import sys
import tempfile
import unittest

SCRIPTS = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
import relocalisation_benchmark  # noqa: E402


class RelocalisationBenchmarkTest(unittest.TestCase):
    def test_parse_drops(self):
        self.assertEqual(relocalisation_benchmark.parse_drops("100:12,200:3"),
                         [(100, 12), (200, 3)])
        self.assertEqual(relocalisation_benchmark.parse_drops(""), [])

    def test_dropped_copy_leaves_out_the_ranges_and_links_the_rest(self):
        with tempfile.TemporaryDirectory() as tmp:
            source = os.path.join(tmp, "seq")
            os.makedirs(os.path.join(source, "rgb"))
            for name in ("rgb.txt", "depth.txt"):
                with open(os.path.join(source, name), "w") as f:
                    f.write("# header\n")
                    f.writelines(f"{1000 + i}.0 {name[:-4]}/{i}.png\n" for i in range(10))
            with open(os.path.join(source, "groundtruth.txt"), "w") as f:
                f.write("# gt\n")
            out = relocalisation_benchmark.dropped_copy(source, [(2, 3), (8, 1)],
                                                        os.path.join(tmp, "copy"))
            with open(os.path.join(out, "rgb.txt")) as f:
                lines = f.read().splitlines()
            self.assertEqual(lines[0], "# header")
            self.assertEqual([line.split()[0] for line in lines[1:]],
                             ["1000.0", "1001.0", "1005.0", "1006.0", "1007.0", "1009.0"])
            self.assertTrue(os.path.islink(os.path.join(out, "rgb")))
            self.assertTrue(os.path.islink(os.path.join(out, "groundtruth.txt")))
            # A second call keeps the copy as it is.
            relocalisation_benchmark.dropped_copy(source, [(2, 3), (8, 1)], out)
            with open(os.path.join(out, "depth.txt")) as f:
                self.assertEqual(len(f.read().splitlines()), 7)

    def test_blanked_frames_point_at_black_images_of_the_same_size(self):
        import cv2
        import numpy as np
        with tempfile.TemporaryDirectory() as tmp:
            source = os.path.join(tmp, "seq")
            os.makedirs(os.path.join(source, "rgb"))
            cv2.imwrite(os.path.join(source, "rgb", "0.png"), np.full((3, 4, 3), 200, np.uint8))
            for name in ("rgb.txt", "depth.txt"):
                with open(os.path.join(source, name), "w") as f:
                    f.writelines(f"{1000 + i}.0 {name[:-4]}/{i}.png\n" for i in range(6))
            out = relocalisation_benchmark.dropped_copy(source, [(0, 1)],
                                                        os.path.join(tmp, "copy"), [(2, 2)])
            with open(os.path.join(out, "depth.txt")) as f:
                lines = f.read().splitlines()
            self.assertEqual(lines, ["1001.0 depth/1.png", "1002.0 blank_depth.png",
                                     "1003.0 blank_depth.png", "1004.0 depth/4.png",
                                     "1005.0 depth/5.png"])
            black = cv2.imread(os.path.join(out, "blank_rgb.png"))
            self.assertEqual(black.shape, (3, 4, 3))
            self.assertEqual(int(black.max()), 0)
            depth = cv2.imread(os.path.join(out, "blank_depth.png"), cv2.IMREAD_UNCHANGED)
            self.assertEqual((depth.dtype, int(depth.max())), (np.uint16, 0))


if __name__ == "__main__":
    unittest.main()
