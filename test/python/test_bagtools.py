"""Tests of the bagtools Python tools: tum_to_bag and plot_trajectory, on tiny synthetic data."""

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


def random_rotation(rng):
    q = rng.normal(size=4)
    return trajectory.quaternion_to_matrix(*q)


def random_trajectory(rng, count):
    """`count` poses along a wavy 3D path with random orientations, stamps at 30 Hz."""
    stamps = 1548339829.5 + np.arange(count) / 30.0
    poses = np.tile(np.eye(4), (count, 1, 1))
    s = np.linspace(0.0, 2.0, count)
    poses[:, :3, 3] = np.stack([s, np.sin(3 * s), 0.3 * np.cos(2 * s)], axis=1)
    for pose in poses:
        pose[:3, :3] = random_rotation(rng)
    return stamps, poses


class TrajectoryTest(TempDirTest):
    def test_quaternion_round_trip(self):
        rng = np.random.RandomState(7)
        for _ in range(20):
            rotation = random_rotation(rng)
            back = trajectory.quaternion_to_matrix(*trajectory.matrix_to_quaternion(rotation))
            np.testing.assert_allclose(back, rotation, atol=1e-12)

    def test_associate_is_greedy_nearest_within_window(self):
        index_a, index_b = trajectory.associate([1.0, 1.01, 2.0, 3.0], [1.005, 1.012, 2.5], 0.02)
        self.assertEqual((index_a.tolist(), index_b.tolist()), ([0, 1], [0, 1]))
        index_a, index_b = trajectory.associate([1.0, 1.004], [1.003], 0.02)
        self.assertEqual((index_a.tolist(), index_b.tolist()), ([1], [0]))

    def test_umeyama_recovers_rigid_transform(self):
        rng = np.random.RandomState(3)
        points = rng.uniform(-2, 2, size=(50, 3))
        truth = np.eye(4)
        truth[:3, :3] = random_rotation(rng)
        truth[:3, 3] = [0.5, -1.0, 2.0]
        moved = points.dot(truth[:3, :3].T) + truth[:3, 3]
        np.testing.assert_allclose(trajectory.umeyama_se3(points, moved), truth, atol=1e-10)

    def test_bonn_correction_is_the_documented_product(self):
        rng = np.random.RandomState(11)
        _, marker = random_trajectory(rng, 5)
        camera = trajectory.bonn_marker_to_camera(marker)
        t_m = trajectory.BONN_T_M_RAW.copy()
        t_m[:3, :3] = trajectory.nearest_rotation(t_m[:3, :3])
        ros = trajectory.BONN_T_ROS
        for gt, cam in zip(marker, camera):
            np.testing.assert_allclose(cam, ros.dot(gt).dot(ros).dot(t_m), atol=1e-12)
            np.testing.assert_allclose(cam[:3, :3].dot(cam[:3, :3].T), np.eye(3), atol=1e-12)
            self.assertAlmostEqual(np.linalg.det(cam[:3, :3]), 1.0, places=12)
        # The projection keeps T_m's rotation close to the raw (almost orthonormal) block.
        self.assertLess(np.abs(t_m[:3, :3] - trajectory.BONN_T_M_RAW[:3, :3]).max(), 0.1)

    def test_plot_of_rigidly_moved_copy_has_zero_ate(self):
        stamps, poses = random_trajectory(np.random.RandomState(5), 60)
        motion = np.eye(4)
        motion[:3, :3] = trajectory.quaternion_to_matrix(0.1, -0.3, 0.2, 0.9)
        motion[:3, 3] = [3.0, -2.0, 1.0]
        gt_path = os.path.join(self.tmp, "gt.txt")
        est_path = os.path.join(self.tmp, "est.txt")
        png = os.path.join(self.tmp, "plot.png")
        trajectory.write_tum_trajectory(gt_path, stamps, poses)
        trajectory.write_tum_trajectory(est_path, stamps + 0.005,
                                        trajectory.transform_poses(motion, poses))
        code, out, err = run_tool("plot_trajectory", "--groundtruth", gt_path, "--trajectory",
                                  est_path, "--output", png, "--title", "test")
        self.assertEqual(code, 0, err)
        ate = float(re.search(r"ATE RMSE: ([0-9.e+-]+) m \(60 of 60", out).group(1))
        self.assertLess(ate, 1e-5)
        self.assertGreater(os.path.getsize(png), 10000)
        with open(png, "rb") as handle:
            self.assertEqual(handle.read(8), b"\x89PNG\r\n\x1a\n")

    def test_ate_of_perturbed_copy_is_measured(self):
        stamps, poses = random_trajectory(np.random.RandomState(9), 40)
        noisy = poses.copy()
        noisy[::2, 0, 3] += 0.01  # every other pose 1 cm off in x
        result = trajectory.align_and_ate(stamps, poses, stamps, noisy)
        self.assertGreater(result["ate_rmse"], 0.003)
        self.assertLess(result["ate_rmse"], 0.0071)
