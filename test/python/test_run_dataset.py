"""Tests of dslam_run_dataset's command line: the back end's execution mode (--threads), the
fixed feeding rate (--rate) and what the summary JSON and status CSV report about them, on a
short synthetic sequence rendered by dslam_synth; the moving objects (--objects) on their own
thread with --threads, on a short walking sequence; the keyframe map file (--save-keyframe-map),
and a run that localises only in a loaded one (--localisation-only)."""

import csv
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
from dslam_tools import grid_files  # noqa: E402
from dslam_tools import trajectory as traj  # noqa: E402

FRAMES = 30
# static_room, seed 1, 30 frames, back end on, synchronous: about twice the measured ATE of the
# causal and the refined trajectory (see the bound's use).
ATE_BOUND_M = 0.0036  # measured 0.00182 m (causal) and 0.00181 m (refined) at e841b8d
COMMITTED_VOCABULARY = 0x723a8e39b1688a18  # data/vocabulary/orb_vocabulary.bin


def fnv1a64(data):
    """64-bit FNV-1a of `data` (dslam/core/binary_io.h)."""
    value = 14695981039346656037
    for byte in data:
        value = ((value ^ byte) * 1099511628211) % (1 << 64)
    return value


def find_tool(name):
    """A built dslam executable: in devel/lib/dslam of a folder on LD_LIBRARY_PATH (catkin sets
    it when it runs the tests) or of build/ws beside the repository."""
    libs = os.environ.get("LD_LIBRARY_PATH", "").split(":")
    libs.append(os.path.join(HERE, "..", "..", "build", "ws", "devel", "lib"))
    for folder in libs:
        path = os.path.join(folder, "dslam", name)
        if folder and os.access(path, os.X_OK):
            return path
    raise RuntimeError("%s not found (build the workspace first)" % name)


class RunDatasetCliTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="dslam_run_dataset_")
        cls.sequence = os.path.join(cls.tmp, "static_room")
        cls.walking = os.path.join(cls.tmp, "walking")
        for scenario, folder in (("static_room", cls.sequence), ("walking", cls.walking)):
            subprocess.run([find_tool("dslam_synth"), "--scenario", scenario, "--frames",
                            str(FRAMES), "--seed", "1", "--output", folder], check=True,
                           stdout=subprocess.DEVNULL)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def run_tool(self, name, *options):
        """Runs dslam_run_dataset with the back end on; returns (exit code, summary, status
        rows, wall time [s])."""
        out = os.path.join(self.tmp, name)
        start = time.monotonic()
        code = subprocess.run(
            [find_tool("dslam_run_dataset"), "--dataset", self.sequence, "--trajectory",
             out + ".txt", "--summary", out + ".json", "--status", out + ".csv",
             "--refined-trajectory", out + "_refined.txt", "--backend", "on", "--quiet"] +
            list(options), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
        wall_s = time.monotonic() - start
        if code != 0:
            return code, None, None, wall_s
        with open(out + ".json") as handle:
            summary = json.load(handle)
        with open(out + ".csv") as handle:
            rows = list(csv.DictReader(handle))
        return code, summary, rows, wall_s

    def test_synchronous_by_default(self):
        code, summary, rows, _ = self.run_tool("sync")
        self.assertEqual(code, 0)
        self.assertFalse(summary["threads"])
        self.assertEqual(summary["rate_hz"], 0)
        self.assertEqual(summary["max_backlog"], 0)
        self.assertEqual(summary["frames_with_pose"], FRAMES)
        self.assertGreater(summary["median_tracking_ms"], 0)
        self.assertGreaterEqual(summary["p95_tracking_ms"], summary["median_tracking_ms"])
        self.assertTrue(all(row["backlog"] == "0" and row["backend_delivered"] == "0"
                            for row in rows))
        self.assertEqual(summary["errors"], 0)
        self.check_trajectories(os.path.join(self.tmp, "sync"))

    def check_trajectories(self, out):
        """The causal and refined trajectory files of the run `out`: one TUM row per frame at the
        colour stamps of rgb.txt, unit quaternions, and both near the ground truth."""
        with open(os.path.join(self.sequence, "rgb.txt")) as handle:
            stamps = [line.split()[0] for line in handle if line.strip() and line[0] != "#"]
        for path, bound_m in ((out + ".txt", ATE_BOUND_M), (out + "_refined.txt", ATE_BOUND_M)):
            with open(path) as handle:
                rows = [line.split() for line in handle if line.strip() and line[0] != "#"]
            self.assertEqual([row[0] for row in rows], stamps, path)
            for row in rows:
                self.assertEqual(len(row), 8, path)
                q = [float(x) for x in row[4:8]]
                self.assertAlmostEqual(sum(x * x for x in q), 1.0, delta=1e-5)
            ate_m = traj.evaluate(os.path.join(self.sequence, "groundtruth.txt"), path)[
                "metrics"]["ate_rmse_m"]
            print("%s: ATE %.5f m" % (os.path.basename(path), ate_m))
            self.assertLess(ate_m, bound_m, path)

    def test_threads_at_a_fixed_rate(self):
        rate_hz = 20.0
        code, summary, rows, wall_s = self.run_tool("threads", "--threads", "--rate", "20")
        self.assertEqual(code, 0)
        self.assertTrue(summary["threads"])
        self.assertEqual(summary["rate_hz"], rate_hz)
        self.assertEqual(summary["frames_with_pose"], FRAMES)
        # The last frame is handed over no earlier than (FRAMES - 1) / rate after the first.
        self.assertGreaterEqual(wall_s, (FRAMES - 1) / rate_hz)
        keyframes = [row for row in rows if row["keyframe"] == "1"]
        self.assertGreater(len(keyframes), 1)
        # A keyframe queues itself: the backlog after it is at least one.
        self.assertTrue(all(int(row["backlog"]) >= 1 for row in keyframes))
        self.assertEqual(summary["max_backlog"], max(int(row["backlog"]) for row in rows))
        self.assertGreater(summary["median_tracking_ms"], 0)
        # Runs are reported by a later frame, flagged; the summary counts each once: those the
        # frames reported (local BA or the window's static point determination ran: points > 0)
        # and at most one completed after the last.
        delivered = [row for row in rows if row["backend_delivered"] == "1"]
        self.assertGreater(len(delivered), 0)
        self.assertLessEqual(len(delivered), len(keyframes))
        ran = sum(int(row["ba_points"]) > 0 or int(row["spd_points"]) > 0 for row in delivered)
        self.assertGreaterEqual(summary["backend_runs"], ran)
        self.assertLessEqual(summary["backend_runs"], ran + 1)

    def objects_run(self, name, *options):
        """Runs dslam_run_dataset --objects on the walking sequence (back end off: the front end
        is then the same with and without --threads); returns (objects file, summary)."""
        out = os.path.join(self.tmp, name)
        subprocess.run(
            [find_tool("dslam_run_dataset"), "--dataset", self.walking, "--trajectory",
             out + ".txt", "--summary", out + ".json", "--objects", out + "_objects.txt",
             "--backend", "off", "--quiet"] + list(options),
            check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(out + "_objects.txt") as handle:
            objects = handle.read()
        with open(out + ".json") as handle:
            return objects, json.load(handle)

    def test_objects_on_their_own_thread_write_the_same_file(self):
        synchronous, sync_summary = self.objects_run("objects_sync")
        threaded, thread_summary = self.objects_run("objects_threads", "--threads", "--rate", "30")
        lines = [line for line in synchronous.splitlines() if not line.startswith("#")]
        self.assertGreater(len(lines), 0)  # the walker is tracked within 30 frames
        self.assertEqual(threaded, synchronous)
        self.assertEqual(thread_summary["object_frames"], len(lines))
        self.assertEqual(sync_summary["object_frames"], len(lines))
        self.assertIn("median_objects_add_ms", thread_summary)

    def test_grid_files(self):
        """--grid writes map_server's pair (include/dslam/mapping/occupancy_grid.h): the YAML's
        keys, a binary PGM of the YAML's image name whose occupied (0) and free (254) pixels are
        the summary's counts, both present, and nothing but 0, 254 and 205."""
        path = os.path.join(self.tmp, "grid.yaml")
        code, summary, _, _ = self.run_tool("grid", "--grid", path)
        self.assertEqual(code, 0)
        keys, image = grid_files.read_grid(path)  # read_pgm checks the size against the pixels
        self.assertEqual(keys["image"], "grid.pgm")
        self.assertEqual(float(keys["resolution"]), 0.05)  # map.voxel_size_m's default
        self.assertEqual(len(keys["origin"].strip("[]").split(",")), 3)
        self.assertEqual((keys["negate"], keys["occupied_thresh"], keys["free_thresh"],
                          keys["mode"]), ("0", "0.65", "0.196", "trinary"))
        pixels = image.tobytes()
        self.assertEqual(set(pixels) - {0, 254, 205}, set())
        self.assertEqual(pixels.count(0), summary["grid_occupied_cells"])
        self.assertEqual(pixels.count(254), summary["grid_free_cells"])
        self.assertGreater(summary["grid_occupied_cells"], 0)
        self.assertGreater(summary["grid_free_cells"], 0)

    def test_octomap_file(self):
        """--octomap writes OctoMap's binary file (octomap_file.h; the C++ test reads one back
        with liboctomap): its header lines and the summary's leaf counts."""
        path = os.path.join(self.tmp, "map.bt")
        code, summary, _, _ = self.run_tool("octomap", "--octomap", path)
        self.assertEqual(code, 0)
        with open(path, "rb") as handle:
            lines = [handle.readline() for _ in range(7)]
        self.assertEqual(lines[0], b"# Octomap OcTree binary file\n")
        self.assertIn(b"id OcTree\n", lines)
        self.assertIn(b"res 0.05\n", lines)
        self.assertGreater(summary["octomap_occupied_leaves"], 0)
        self.assertGreater(summary["octomap_free_leaves"], 0)

    def test_save_keyframe_map(self):
        """The header of the keyframe map file (include/dslam/map_file/keyframe_map_file.h):
        version 2, size, checksum, the sequence's camera, the committed vocabulary's identity
        (loop closing on or off), images of every keyframe and the settings; synchronous and with
        --threads."""
        for name, options in (("kfm_sync", ["--loop-closing", "off"]), ("kfm_threads", ["--threads"])):
            path = os.path.join(self.tmp, name + ".bin")
            code, summary, _, _ = self.run_tool(name, "--save-keyframe-map", path, *options)
            self.assertEqual(code, 0, name)
            with open(path, "rb") as handle:
                data = handle.read()
            magic, version, size, checksum = struct.unpack_from("<8sIQQ", data, 0)
            self.assertEqual((magic, version, size), (b"DSLAMKFM", 2, len(data)), name)
            self.assertEqual(checksum, fnv1a64(data[28:]), name)
            width, height = struct.unpack_from("<II", data, 28)
            with open(os.path.join(self.sequence, "camera.yaml")) as handle:
                camera = dict(line.split(":", 1) for line in handle if ":" in line)
            self.assertEqual((width, height), (int(camera["width"]), int(camera["height"])))
            identity, points, keyframes, images = struct.unpack_from("<QIII", data, 108)
            self.assertEqual(identity, COMMITTED_VOCABULARY, name)
            self.assertGreater(points, 100, name)
            self.assertGreater(keyframes, 1, name)
            self.assertEqual(images, keyframes, name)  # the map keeps every keyframe of 30 frames
            # Version 2's settings: the default config's ORB pyramid and depth noise model.
            levels, scale, pixel_sigma = struct.unpack_from("<Idd", data, 128)
            self.assertEqual((levels, scale, pixel_sigma), (8, 1.2, 1.0), name)
            self.assertFalse([f for f in os.listdir(self.tmp) if ".tmp-" in f])

    def test_localisation_only_saves_the_loaded_map_unchanged(self):
        """--localisation-only with --load-keyframe-map: the map saved at the end is the loaded
        file, byte for byte, and the summary says so; without --load-keyframe-map the option is
        a usage error that names it."""
        loaded = os.path.join(self.tmp, "lo_loaded.bin")
        code, _, _, _ = self.run_tool("lo_first", "--save-keyframe-map", loaded)
        self.assertEqual(code, 0)
        saved = os.path.join(self.tmp, "lo_saved.bin")
        code, summary, _, _ = self.run_tool("lo_second", "--load-keyframe-map", loaded,
                                            "--localisation-only", "--save-keyframe-map", saved)
        self.assertEqual(code, 0)
        self.assertTrue(summary["keyframe_map_loaded"])
        self.assertTrue(summary["localisation_only"])
        self.assertGreater(summary["frames_with_pose"], FRAMES // 2)
        with open(loaded, "rb") as a, open(saved, "rb") as b:
            self.assertEqual(a.read(), b.read())
        usage = subprocess.run(
            [find_tool("dslam_run_dataset"), "--dataset", self.sequence, "--trajectory",
             os.path.join(self.tmp, "lo_bad.txt"), "--localisation-only"],
            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, universal_newlines=True)
        self.assertEqual(usage.returncode, 2)
        self.assertIn("--localisation-only needs --load-keyframe-map", usage.stderr)

    def test_saving_over_a_keyframe_map_keeps_it_as_prev(self):
        """--save-keyframe-map over an existing file (here the map the run extends) keeps that
        file as OUT.bin.prev, byte for byte; no temporary file is left."""
        path = os.path.join(self.tmp, "prev_map.bin")
        code, _, _, _ = self.run_tool("prev_first", "--save-keyframe-map", path)
        self.assertEqual(code, 0)
        with open(path, "rb") as handle:
            first = handle.read()
        self.assertFalse(os.path.exists(path + ".prev"))
        code, summary, _, _ = self.run_tool("prev_second", "--load-keyframe-map", path,
                                            "--save-keyframe-map", path)
        self.assertEqual(code, 0)
        self.assertTrue(summary["keyframe_map_loaded"])
        with open(path + ".prev", "rb") as handle:
            self.assertEqual(handle.read(), first)
        with open(path, "rb") as handle:
            self.assertNotEqual(handle.read(), first)  # the extended map
        self.assertFalse([f for f in os.listdir(self.tmp) if ".tmp-" in f])

    def test_bad_rate_is_a_usage_error(self):
        for value in ["0", "-5", "fast"]:
            code, _, _, _ = self.run_tool("bad", "--rate", value)
            self.assertEqual(code, 2, value)


if __name__ == "__main__":
    unittest.main()
