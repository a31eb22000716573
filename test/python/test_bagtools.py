"""Tests of the bagtools Python tools: tum_to_bag and plot_trajectory, on tiny synthetic data.
plot_trajectory and the EvalToolTest cases run the built C++ tool dslam_eval."""

import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

import cv2
import numpy as np
import rosbag

SCRIPTS = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
from dslam_tools import dataset, trajectory, tum_bag  # noqa: E402

WIDTH, HEIGHT = 8, 6
RGB_STAMPS = ["1305031453.359684", "1305031453.391690"]
DEPTH_STAMPS = ["1305031453.3", "1305031453.374394", "1305031453.403385"]
CAMERA_YAML = """width: 8
height: 6
fx: 517.3
fy: 516.5
cx: 3.6
cy: 2.3
k1: 0.2624
k2: -0.9531
p1: -0.0054
p2: 0.0026
k3: 1.1633
depth_scale: 5000.0
groundtruth_correction: none
"""


def colour_image(index):
    """RGB [H,W,3] with distinct channels: R = 10 + index, G = column, B = 100 + row."""
    rgb = np.zeros((HEIGHT, WIDTH, 3), np.uint8)
    rgb[:, :, 0] = 10 + index
    rgb[:, :, 1] = np.arange(WIDTH)[None, :]
    rgb[:, :, 2] = 100 + np.arange(HEIGHT)[:, None]
    return rgb


def depth_image(index):
    """16-bit depth: 5000 * (1 + index) everywhere, 12345 at (row 1, col 2), 0 at (0, 0)."""
    depth = np.full((HEIGHT, WIDTH), 5000 * (1 + index), np.uint16)
    depth[1, 2] = 12345
    depth[0, 0] = 0
    return depth


def write_list(folder, name, kind, stamps):
    os.makedirs(os.path.join(folder, kind))
    with open(os.path.join(folder, name), "w") as handle:
        handle.write("# %s\n# timestamp filename\n" % kind)
        for stamp in stamps:
            handle.write("%s %s/%s.png\n" % (stamp, kind, stamp))


def make_tum_folder(folder, with_mask=False):
    """A TUM-layout folder: 2 colour frames, 3 depth images, camera.yaml, optional masks."""
    write_list(folder, "rgb.txt", "rgb", RGB_STAMPS)
    write_list(folder, "depth.txt", "depth", DEPTH_STAMPS)
    for i, stamp in enumerate(RGB_STAMPS):
        bgr = cv2.cvtColor(colour_image(i), cv2.COLOR_RGB2BGR)
        assert cv2.imwrite(os.path.join(folder, "rgb", stamp + ".png"), bgr)
    for i, stamp in enumerate(DEPTH_STAMPS):
        assert cv2.imwrite(os.path.join(folder, "depth", stamp + ".png"), depth_image(i))
    if with_mask:
        write_list(folder, "mask.txt", "mask", RGB_STAMPS)
        for i, stamp in enumerate(RGB_STAMPS):
            mask = np.zeros((HEIGHT, WIDTH), np.uint16)
            mask[2:4, 3:6] = 300 + i
            assert cv2.imwrite(os.path.join(folder, "mask", stamp + ".png"), mask)
    with open(os.path.join(folder, "camera.yaml"), "w") as handle:
        handle.write(CAMERA_YAML)


def run_tool(name, *args):
    """Runs a script of scripts/ with this interpreter; returns (exit code, stdout, stderr)."""
    process = subprocess.Popen([sys.executable, os.path.join(SCRIPTS, name)] + list(args),
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               universal_newlines=True)
    out, err = process.communicate()
    return process.returncode, out, err


def read_bag(path):
    """{topic: [(message, record time)]} of a bag."""
    messages = {}
    with rosbag.Bag(path) as bag:
        for topic, message, stamp in bag.read_messages():
            messages.setdefault(topic, []).append((message, stamp))
    return messages


class TempDirTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="dslam_bagtools_")

    def tearDown(self):
        shutil.rmtree(self.tmp)


class TumToBagTest(unittest.TestCase):
    """Converts the synthetic folder once with the command-line tool; tests read the bag."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="dslam_bagtools_")
        cls.folder = os.path.join(cls.tmp, "tum")
        os.makedirs(cls.folder)
        make_tum_folder(cls.folder, with_mask=True)
        output = os.path.join(cls.tmp, "out.bag")
        cls.code, cls.out, cls.err = run_tool("tum_to_bag", cls.folder, output)
        cls.bag = read_bag(output) if cls.code == 0 else {}

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def convert(self):
        self.assertEqual(self.code, 0, self.err)
        self.assertIn("2 colour, 3 depth, 2 camera_info messages", self.out)
        self.assertTrue(self.err.endswith("] 5/5\n"), self.err)  # progress bar reached the end
        return self.bag

    def test_topics_encodings_frames_and_stamps(self):
        bag = self.convert()
        self.assertEqual(sorted(bag), sorted([tum_bag.RGB_TOPIC, tum_bag.DEPTH_TOPIC,
                                              tum_bag.INFO_TOPIC]))
        self.assertEqual([len(bag[t]) for t in (tum_bag.RGB_TOPIC, tum_bag.DEPTH_TOPIC,
                                                tum_bag.INFO_TOPIC)], [2, 3, 2])
        for topic, stamps in ((tum_bag.RGB_TOPIC, RGB_STAMPS), (tum_bag.DEPTH_TOPIC, DEPTH_STAMPS),
                              (tum_bag.INFO_TOPIC, RGB_STAMPS)):
            for (message, record_time), text in zip(bag[topic], stamps):
                secs, nsecs = dataset.stamp_to_sec_nsec(text)
                self.assertEqual((message.header.stamp.secs, message.header.stamp.nsecs),
                                 (secs, nsecs))
                self.assertEqual(record_time, message.header.stamp)
                self.assertEqual(message.header.frame_id, "openni_rgb_optical_frame")
        self.assertEqual(bag[tum_bag.RGB_TOPIC][0][0].header.stamp.nsecs, 359684000)
        self.assertEqual(bag[tum_bag.DEPTH_TOPIC][0][0].header.stamp.nsecs, 300000000)

    def test_colour_is_rgb8_in_rgb_order(self):
        for i, (message, _) in enumerate(self.convert()[tum_bag.RGB_TOPIC]):
            self.assertEqual((message.encoding, message.width, message.height, message.step),
                             ("rgb8", WIDTH, HEIGHT, 3 * WIDTH))
            pixels = np.frombuffer(message.data, np.uint8).reshape(HEIGHT, WIDTH, 3)
            np.testing.assert_array_equal(pixels, colour_image(i))

    def test_depth_is_32fc1_metres_with_nan_for_zero(self):
        for i, (message, _) in enumerate(self.convert()[tum_bag.DEPTH_TOPIC]):
            self.assertEqual((message.encoding, message.step, message.is_bigendian),
                             ("32FC1", 4 * WIDTH, 0))
            metres = np.frombuffer(message.data, "<f4").reshape(HEIGHT, WIDTH)
            self.assertTrue(math.isnan(metres[0, 0]))
            self.assertAlmostEqual(float(metres[1, 2]), 12345 / 5000.0, places=6)
            self.assertAlmostEqual(float(metres[5, 7]), 1.0 + i, places=6)
            self.assertEqual(int(np.isnan(metres).sum()), 1)

    def test_depth_conversion_is_the_offline_readers_bit_for_bit(self):
        # DepthFromScaledUint16 multiplies by the float 1 / depth_scale
        # (test/core/depth_conversion_test.cpp checks that side for every value).
        raw = np.arange(1, 65536, dtype=np.uint16).reshape(1, -1)
        for scale in (5000.0, 1000.0):
            expected = raw.astype(np.float32) * np.float32(1.0 / scale)
            self.assertTrue(np.array_equal(tum_bag.depth_to_metres(raw, scale), expected))

    def test_camera_info_from_yaml(self):
        bag = self.convert()
        for (info, _), (image, _) in zip(bag[tum_bag.INFO_TOPIC], bag[tum_bag.RGB_TOPIC]):
            self.assertEqual(info.header.stamp, image.header.stamp)
            self.assertEqual((info.width, info.height, info.distortion_model),
                             (WIDTH, HEIGHT, "plumb_bob"))
            np.testing.assert_allclose(info.K, [517.3, 0, 3.6, 0, 516.5, 2.3, 0, 0, 1])
            np.testing.assert_allclose(info.D, [0.2624, -0.9531, -0.0054, 0.0026, 1.1633])
            np.testing.assert_allclose(info.R, np.eye(3).ravel())
            np.testing.assert_allclose(info.P, [517.3, 0, 3.6, 0, 0, 516.5, 2.3, 0, 0, 0, 1, 0])

    def test_mask_topic_is_mono16(self):
        output = os.path.join(self.tmp, "mask.bag")
        result = tum_bag.convert(self.folder, output, compression="bz2", with_mask=True,
                                 progress=False)
        self.assertEqual(result["counts"][tum_bag.MASK_TOPIC], 2)
        masks = read_bag(output)[tum_bag.MASK_TOPIC]
        self.assertEqual(len(masks), 2)
        pixels = np.frombuffer(masks[1][0].data, "<u2").reshape(HEIGHT, WIDTH)
        self.assertEqual((masks[1][0].encoding, int(pixels[3, 4]), int(pixels[0, 0])),
                         ("mono16", 301, 0))

    def test_size_mismatch_fails_and_leaves_no_bag(self):
        camera = os.path.join(self.tmp, "wrong.yaml")
        with open(camera, "w") as handle:
            handle.write(CAMERA_YAML.replace("width: 8", "width: 640"))
        output = os.path.join(self.tmp, "wrong.bag")
        code, _, err = run_tool("tum_to_bag", self.folder, output, "--camera", camera)
        self.assertEqual(code, 1)
        self.assertIn("camera.yaml says 640x6", err)
        self.assertFalse(os.path.exists(output))


class DatasetTest(unittest.TestCase):
    def test_stamp_text_to_sec_nsec_is_exact(self):
        self.assertEqual(dataset.stamp_to_sec_nsec("1548339829.93029"), (1548339829, 930290000))
        self.assertEqual(dataset.stamp_to_sec_nsec("12"), (12, 0))
        self.assertEqual(dataset.stamp_to_sec_nsec("1.9999999996"), (2, 0))
        self.assertRaises(ValueError, dataset.stamp_to_sec_nsec, "1e9")


def quaternion_to_matrix(q):
    """Rotation matrix of a unit quaternion (qx, qy, qz, qw)."""
    x, y, z, w = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def quaternion_product(a, b):
    """Hamilton product a * b of quaternions (qx, qy, qz, qw): the rotation b, then a."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return np.array([aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz])


def random_trajectory(rng, count):
    """`count` poses along a wavy 3D path with random orientations, stamps at 30 Hz: stamps [N] s,
    positions [N,3] m, unit quaternions [N,4] (qx, qy, qz, qw)."""
    stamps = 1548339829.5 + np.arange(count) / 30.0
    s = np.linspace(0.0, 2.0, count)
    positions = np.stack([s, np.sin(3 * s), 0.3 * np.cos(2 * s)], axis=1)
    quaternions = rng.normal(size=(count, 4))
    quaternions /= np.linalg.norm(quaternions, axis=1)[:, None]
    return stamps, positions, quaternions


def move_rigidly(positions, quaternions, motion_q, motion_t):
    """Poses (positions, quaternions) left-multiplied by the rigid motion (motion_q, motion_t):
    the same trajectory expressed in another world frame."""
    motion_q = np.asarray(motion_q, dtype=float) / np.linalg.norm(motion_q)
    moved_positions = positions.dot(quaternion_to_matrix(motion_q).T) + motion_t
    moved_quaternions = np.array([quaternion_product(motion_q, q) for q in quaternions])
    return moved_positions, moved_quaternions


def write_tum(path, stamps, positions, quaternions):
    """TUM trajectory file: `timestamp tx ty tz qx qy qz qw` per pose."""
    with open(path, "w") as handle:
        handle.write("# timestamp tx ty tz qx qy qz qw\n")
        for stamp, p, q in zip(stamps, positions, quaternions):
            handle.write("%.6f %.6f %.6f %.6f %.7f %.7f %.7f %.7f\n" % ((stamp,) + tuple(p) +
                                                                    tuple(q)))


def run_dslam_eval(*args):
    """Runs the built dslam_eval (found as plot_trajectory finds it); returns (exit code, stdout,
    stderr)."""
    process = subprocess.Popen([trajectory.find_dslam_eval()] + list(args),
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               universal_newlines=True)
    out, err = process.communicate()
    return process.returncode, out, err


MOTION_Q = (0.1, -0.3, 0.2, 0.9)  # rotation of the test's rigid motion (normalised when used)
MOTION_T = (3.0, -2.0, 1.0)  # [m] translation of the test's rigid motion
# Bonn correction, docs/readme/eval.md: T_cam = T_ros T_gt T_ros T_m; T_ros has no translation,
# so the camera position is R_ros (R_gt R_ros t_m + t_gt) whatever T_m's rotation block is.
BONN_R_ROS = np.array([[-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]])
BONN_T_M = np.array([0.0113, -0.0098, 0.0111])  # [m]


class EvalToolTest(TempDirTest):
    """dslam_eval's --save-aligned / --save-groundtruth and plot_trajectory, which runs it."""

    def write(self, name, stamps, positions, quaternions):
        path = os.path.join(self.tmp, name)
        write_tum(path, stamps, positions, quaternions)
        return path

    def moved_copy(self, seed, count, stamp_offset=0.005):
        """Ground truth and an estimate that is the same trajectory in another world frame."""
        stamps, positions, quaternions = random_trajectory(np.random.RandomState(seed), count)
        gt = self.write("gt.txt", stamps, positions, quaternions)
        moved = move_rigidly(positions, quaternions, MOTION_Q, MOTION_T)
        est = self.write("est.txt", stamps + stamp_offset, *moved)
        return gt, est, (stamps, positions, quaternions)

    def test_save_aligned_maps_a_moved_copy_onto_the_groundtruth(self):
        gt, est, (stamps, positions, quaternions) = self.moved_copy(3, 50)
        aligned, matched = os.path.join(self.tmp, "al.txt"), os.path.join(self.tmp, "gt_m.txt")
        metrics = os.path.join(self.tmp, "eval.json")
        code, _, err = run_dslam_eval("--groundtruth", gt, "--trajectory", est, "--json", metrics,
                                      "--save-aligned", aligned, "--save-groundtruth", matched)
        self.assertEqual(code, 0, err)
        with open(metrics) as handle:
            numbers = json.load(handle)
        self.assertEqual((numbers["associated_poses"], numbers["estimated_poses"]), (50, 50))
        self.assertLess(numbers["ate_rmse_m"], 1e-5)
        rows, truth = np.loadtxt(aligned, ndmin=2), np.loadtxt(matched, ndmin=2)
        np.testing.assert_allclose(rows[:, 0], stamps + 0.005, atol=1e-6)
        np.testing.assert_allclose(rows[:, 1:4], positions, atol=1e-5)
        dots = np.abs(np.sum(rows[:, 4:8] * quaternions, axis=1))  # q and -q: the same rotation
        np.testing.assert_allclose(dots, np.ones(50), atol=1e-6)
        np.testing.assert_allclose(truth[:, 0], stamps, atol=1e-6)
        np.testing.assert_allclose(truth[:, 1:4], positions, atol=1e-6)

    def test_plot_of_rigidly_moved_copy_has_zero_ate(self):
        gt, est, _ = self.moved_copy(5, 60)
        png = os.path.join(self.tmp, "plot.png")
        code, out, err = run_tool("plot_trajectory", "--groundtruth", gt, "--trajectory", est,
                                  "--output", png, "--title", "test")
        self.assertEqual(code, 0, err)
        ate = float(re.search(r"ATE RMSE: ([0-9.e+-]+) m \(60 of 60", out).group(1))
        self.assertLess(ate, 1e-5)
        self.assertIn("ground-truth correction: none", out)
        self.assertGreater(os.path.getsize(png), 10000)
        with open(png, "rb") as handle:
            self.assertEqual(handle.read(8), b"\x89PNG\r\n\x1a\n")

    def test_ate_of_a_noisy_moved_copy_is_the_noise(self):
        stamps, positions, quaternions = random_trajectory(np.random.RandomState(9), 40)
        gt = self.write("gt.txt", stamps, positions, quaternions)
        noisy = positions.copy()
        noisy[:, 0] += 0.005 * (-1.0) ** np.arange(40)  # +-5 mm in x, alternating
        est = self.write("est.txt", stamps, *move_rigidly(noisy, quaternions, MOTION_Q, MOTION_T))
        result = trajectory.evaluate(gt, est)
        ate = result["metrics"]["ate_rmse_m"]
        # Identity alignment leaves exactly 5 mm RMS and Umeyama minimises the sum of squares; the
        # alternating offsets barely correlate with the smooth path, so little is absorbed.
        self.assertLess(ate, 0.005 + 1e-6)
        self.assertGreater(ate, 0.0045)
        self.assertEqual(len(result["errors"]), 40)
        self.assertAlmostEqual(float(np.sqrt(np.mean(result["errors"] ** 2))), ate, delta=2e-6)

    def test_association_is_greedy_nearest_within_max_dt(self):
        gt_stamps = np.array([1.003, 2.0, 3.0, 4.0])
        est_stamps = np.array([1.0, 1.004, 2.01, 3.5, 4.0])
        corners = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], dtype=float)
        identity = np.tile([0.0, 0.0, 0.0, 1.0], (5, 1))
        gt = self.write("gt.txt", gt_stamps, corners[:4], identity[:4])
        est = self.write("est.txt", est_stamps, corners, identity)
        # 1.004 takes 1.003 (|dt| 1 ms beats 1.0's 3 ms); 3.5 has no partner within 20 ms.
        result = trajectory.evaluate(gt, est)
        self.assertEqual((result["metrics"]["associated_poses"],
                          result["metrics"]["estimated_poses"]), (3, 5))
        np.testing.assert_allclose(result["aligned"][0], [1.004, 2.01, 4.0], atol=1e-9)
        np.testing.assert_allclose(result["matched"][0], [1.003, 2.0, 4.0], atol=1e-9)
        narrow = trajectory.evaluate(gt, est, max_dt=0.005)
        self.assertEqual(narrow["metrics"]["max_association_dt_s"], 0.005)
        np.testing.assert_allclose(narrow["matched"][0], [1.003, 4.0], atol=1e-9)

    def test_bonn_correction_moves_the_groundtruth_as_documented(self):
        stamps, positions, quaternions = random_trajectory(np.random.RandomState(11), 30)
        gt = self.write("gt.txt", stamps, positions, quaternions)
        camera = os.path.join(self.tmp, "camera.yaml")
        with open(camera, "w") as handle:
            handle.write(CAMERA_YAML.replace("groundtruth_correction: none",
                                             "groundtruth_correction: bonn"))
        result = trajectory.evaluate(gt, gt, camera)
        self.assertEqual(result["metrics"]["groundtruth_correction"], "bonn")
        expected = np.array([BONN_R_ROS.dot(quaternion_to_matrix(q).dot(BONN_R_ROS.dot(BONN_T_M))
                                            + p) for p, q in zip(positions, quaternions)])
        np.testing.assert_allclose(result["groundtruth"][1], expected, atol=2e-6)
        plain = trajectory.evaluate(gt, gt)
        self.assertEqual(plain["metrics"]["groundtruth_correction"], "none")
        np.testing.assert_allclose(plain["groundtruth"][1], positions, atol=1e-6)
        code, out, err = run_tool("plot_trajectory", "--groundtruth", gt, "--trajectory", gt,
                                  "--camera", camera, "--output", os.path.join(self.tmp, "b.png"))
        self.assertEqual(code, 0, err)
        self.assertIn("(30 of 30 estimated poses associated, ground-truth correction: bonn)", out)

    def test_plot_reports_dslam_eval_errors(self):
        stamps, positions, quaternions = random_trajectory(np.random.RandomState(1), 10)
        gt = self.write("gt.txt", stamps, positions, quaternions)
        est = self.write("est.txt", stamps + 100.0, positions, quaternions)
        png = os.path.join(self.tmp, "none.png")
        code, _, err = run_tool("plot_trajectory", "--groundtruth", gt, "--trajectory", est,
                                "--output", png)
        self.assertEqual(code, 1)
        self.assertIn("no estimated pose has a ground-truth pose within", err)
        self.assertFalse(os.path.exists(png))
