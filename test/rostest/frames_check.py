#!/usr/bin/env python3
"""rostest (frames.test): the TF tree and the topics docs/ros-interface.md promises ("Frames and
conventions", "Published topics"), on nodes this script launches (dslam.launch, exact sync) and
feeds frame by frame with a rendered static_room sequence (colour frame id `cam`):
1. defaults: the default camera mount on /tf_static (optical z = base x, x = -y, y = -z, at the
   base origin); map -> odom and odom -> base_link on /tf for each frame; odom's covariance 1e6
   ("unknown") at the first frame, then a positive definite one; `features` a bgr8 image of
   each frame; `keyframe_path` in map, emptied by the reset service and refilled by new keyframes;
2. publish_map_tf and publish_tf false, camera_frame `my_camera`, its mount (rotated off the
   default) on /tf_static from this script within tf_wait_s: nothing on /tf from the
   node, no default mount published, the path in odom_frame, and odom's base poses those of the
   saved camera poses through that mount."""

import os
import sys
import tempfile
import unittest

import numpy as np
import rospkg
import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import Path
from sensor_msgs.msg import Image
from std_srvs.srv import Trigger
from tf2_msgs.msg import TFMessage

from dslam.srv import SaveTrajectory

sys.path.insert(0, os.path.join(rospkg.RosPack().get_path("dslam"), "scripts"))
import test_scenes  # noqa: E402 (beside this file)
from frame_sender import Sequence, start_node, stop  # noqa: E402 (beside this file)
from rostest_helpers import matrix, tum_matrix  # noqa: E402 (beside this file)

FRAMES = 60
T0 = 1000.0
# base <- optical of the default mount: optical x = base -y, y = base -z, z = base x.
R_BASE_OPTICAL = np.array([[0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], [0.0, -1.0, 0.0]])


def transforms(rec, name, parent, child):
    """The TransformStamped of `parent` -> `child` recorded as `name`, in arrival order."""
    return [t for msg in rec.messages(name) for t in msg.transforms
            if t.header.frame_id == parent and t.child_frame_id == child]


class FramesTest(unittest.TestCase):
    def test_in_order(self):
        rospy.init_node("frames_check")
        work = tempfile.mkdtemp(prefix="dslam_frames_")
        folder, _ = test_scenes.scene("static_room", FRAMES, with_bag=True)  # as odometry_bag's
        seq = Sequence(folder)
        self.check_defaults(work, seq)
        self.check_mount_from_tf_and_no_tf(work, seq)

    def start(self, work, ns, params):
        return start_node(work, ns, params=params, topics=[
            ("/tf_static", TFMessage, "tf_static"), ("/%s/features" % ns, Image, "features"),
            ("/%s/keyframe_path" % ns, Path, "keyframe_path")])

    def check_defaults(self, work, seq):
        process, node = self.start(work, "dslam_defaults", {})
        try:
            statuses = [node.send(seq.messages(i, T0 + i / 30.0)) for i in range(15)]
            self.assertEqual([s.state for s in statuses], ["initialised"] + ["tracking"] * 14)
            rospy.sleep(0.5)  # the latched keyframe_path and the last images arrive
            before = node.rec.last("keyframe_path")
            self.assertTrue(rospy.ServiceProxy("/dslam_defaults/reset", Trigger)().success)
            reset_stamp = T0 + 15 / 30.0
            statuses = [node.send(seq.messages(i, T0 + i / 30.0)) for i in range(15, 25)]
            self.assertTrue(statuses[0].reset)
            rospy.sleep(0.5)
        finally:
            stop(process)
        self.check_default_mount(node)
        self.check_tf_and_odom(node)
        images = node.rec.messages("features")
        self.assertGreaterEqual(len(images), 24)
        self.assertEqual((images[0].encoding, images[0].width, images[0].height),
                         ("bgr8", 640, 480))
        self.assertEqual(images[0].header.stamp.to_sec(), T0)
        # keyframe_path: the map's keyframes in map, emptied by the reset and refilled.
        self.assertEqual(before.header.frame_id, "map")
        self.assertGreaterEqual(len(before.poses), 2)
        after = [m for m in node.rec.messages("keyframe_path")
                 if m.poses and m.poses[0].header.stamp.to_sec() >= reset_stamp - 1e-6]
        self.assertTrue(after, "no keyframe_path of the new map")
        self.assertTrue(all(p.header.stamp.to_sec() >= reset_stamp - 1e-6
                            for p in node.rec.last("keyframe_path").poses))

    def check_default_mount(self, node):
        mounts = transforms(node.rec, "tf_static", "base_link", "cam")
        self.assertEqual(len(mounts), 1, "the default mount, once")
        t = mounts[0].transform
        self.assertEqual((t.translation.x, t.translation.y, t.translation.z), (0.0, 0.0, 0.0))
        np.testing.assert_allclose(matrix(t.translation, t.rotation)[:3, :3], R_BASE_OPTICAL,
                                   atol=1e-9)

    def check_tf_and_odom(self, node):
        odoms = node.rec.messages("odom")
        self.assertEqual(len(odoms), 24)  # 25 frames; the one after the reset has no pose
        stamps = [o.header.stamp.to_nsec() for o in odoms]
        base = {t.header.stamp.to_nsec() for t in transforms(node.rec, "tf", "odom", "base_link")}
        maps = {t.header.stamp.to_nsec() for t in transforms(node.rec, "tf", "map", "odom")}
        self.assertEqual(base, set(stamps))
        self.assertEqual(maps, set(stamps))
        first = np.array(odoms[0].pose.covariance).reshape(6, 6)
        self.assertEqual(list(np.diag(first)), [1e6] * 6)  # the first frame: unknown
        for odom in odoms[1:]:
            covariance = np.array(odom.pose.covariance).reshape(6, 6)
            np.testing.assert_allclose(covariance, covariance.T, atol=1e-12)
            eigen = np.linalg.eigvalsh(covariance)
            self.assertTrue(0.0 < eigen.min() and eigen.max() < 1.0, eigen)

    def check_mount_from_tf_and_no_tf(self, work, seq):
        # The optical frame yawed 30 deg about the base's z axis and lifted: not the default.
        yaw = np.radians(30.0)
        R_yaw = np.array([[np.cos(yaw), -np.sin(yaw), 0.0], [np.sin(yaw), np.cos(yaw), 0.0],
                          [0.0, 0.0, 1.0]])
        T_base_camera = np.identity(4)
        T_base_camera[:3, :3] = R_yaw @ R_BASE_OPTICAL
        T_base_camera[:3, 3] = [0.10, 0.0, 0.25]
        mount = TransformStamped()
        mount.header.stamp = rospy.Time.now()
        mount.header.frame_id, mount.child_frame_id = "base_b", "my_camera"
        mount.transform.translation.x, mount.transform.translation.z = 0.10, 0.25
        q = mount.transform.rotation
        q.x, q.y, q.z, q.w = rotation_quaternion(T_base_camera[:3, :3])
        broadcaster = tf2_ros.StaticTransformBroadcaster()
        broadcaster.sendTransform(mount)
        params = {"publish_map_tf": "false", "publish_tf": "false", "camera_frame": "my_camera",
                  "tf_wait_s": "5.0", "base_frame": "base_b", "odom_frame": "odom_b",
                  "map_frame": "map_b"}
        process, node = self.start(work, "dslam_mounted", params)
        try:
            for i in range(20):
                self.assertNotEqual(node.send(seq.messages(i, T0 + i / 30.0)).state, "rejected")
            rospy.sleep(0.5)
            out = os.path.join(work, "mounted.txt")
            reply = rospy.ServiceProxy("/dslam_mounted/save_trajectory", SaveTrajectory)(out)
            self.assertTrue(reply.success, reply.message)
        finally:
            stop(process)
        tf_frames = {(t.header.frame_id, t.child_frame_id)
                     for msg in node.rec.messages("tf") for t in msg.transforms}
        self.assertFalse({("map_b", "odom_b"), ("odom_b", "base_b")} & tf_frames, tf_frames)
        for t in transforms(node.rec, "tf_static", "base_b", "my_camera"):  # this script's only
            self.assertAlmostEqual(t.transform.translation.z, 0.25)
        self.assertEqual(node.rec.last("path").header.frame_id, "odom_b")
        camera = {int(round(row[0] * 1e6)): tum_matrix(row)
                  for row in np.loadtxt(out, comments="#", ndmin=2)}
        odoms = node.rec.messages("odom")
        self.assertEqual(len(odoms), 20)
        self.assertEqual(odoms[0].header.frame_id, "odom_b")
        self.assertEqual(odoms[0].child_frame_id, "base_b")
        worst = 0.0
        for odom in odoms:
            T_cam0_cam = camera[int(round(odom.header.stamp.to_sec() * 1e6))]
            expected = T_base_camera @ T_cam0_cam @ np.linalg.inv(T_base_camera)
            got = matrix(odom.pose.pose.position, odom.pose.pose.orientation)
            worst = max(worst, np.abs(got - expected).max())
        rospy.loginfo("frames_check: odom against the saved poses through the mount: %.2e", worst)
        self.assertLess(worst, 1e-5)


def rotation_quaternion(R):
    """(x, y, z, w) of the rotation matrix `R` (w > 0 branch; R is far from a half turn here)."""
    w = 0.5 * np.sqrt(1.0 + R[0, 0] + R[1, 1] + R[2, 2])
    return [(R[2, 1] - R[1, 2]) / (4 * w), (R[0, 2] - R[2, 0]) / (4 * w),
            (R[1, 0] - R[0, 1]) / (4 * w), w]


if __name__ == "__main__":
    rostest.rosrun("dslam", "frames_check", FramesTest)
