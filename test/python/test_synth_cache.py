"""Tests of scripts/dslam_tools/synth_cache.py: which rendered folders the benchmarks use again.
Builds and runs nothing of dslam."""

import os
import sys
import tempfile
import unittest

SCRIPTS = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
from dslam_tools import synth_cache  # noqa: E402


def folder_with(files):
    """A new folder holding `files` ({name: text})."""
    folder = tempfile.mkdtemp(prefix="dslam_synth_cache_")
    for name, text in files.items():
        with open(os.path.join(folder, name), "w") as out:
            out.write(text)
    return folder


class SynthCacheTest(unittest.TestCase):
    def test_a_gaussian_scene_needs_its_depth_noise_in_camera_yaml(self):
        stated = "fx: 525\ndepth_sigma_d_quadratic: 0.0014\ndepth_sigma_d_constant_m: 0.001\n"
        self.assertTrue(synth_cache.is_current(
            folder_with({"groundtruth.txt": "", "camera.yaml": stated}), "walking"))
        self.assertFalse(synth_cache.is_current(
            folder_with({"groundtruth.txt": "", "camera.yaml": "fx: 525\n"}), "walking"))
        self.assertFalse(synth_cache.is_current(folder_with({"groundtruth.txt": ""}), "walking"))

    def test_a_structured_light_scene_states_none(self):
        self.assertTrue(synth_cache.is_current(
            folder_with({"groundtruth.txt": "", "camera.yaml": "fx: 525\n"}), "walking_kinect"))

    def test_every_named_file_must_exist(self):
        stated = "depth_sigma_d_quadratic: 0.0014\n"
        folder = folder_with({"groundtruth.txt": "", "camera.yaml": stated})
        self.assertFalse(
            synth_cache.is_current(folder, "walking", ("groundtruth.txt", "objects.txt")))
        self.assertFalse(synth_cache.is_current(os.path.join(folder, "missing"), "walking"))


if __name__ == "__main__":
    unittest.main()
