#!/usr/bin/env python3
"""rostest: hand-made input sets into the dslam nodelet, one at a time (each waits for its status
message), checking the documented behaviour of each robustness case (docs/ros-interface.md, "Frames and
conventions"): skipped sets reported as `rejected`, the reset service keeping the odometry
continuous (and map -> odom), time going backwards starting a new trajectory segment and odom at
the origin, warnings for frame ids, gaps and a missing camera_info, the streamed and saved
segment files, the refined trajectory of the current segment alone, the bounded path, and an invalid parameter stopping dslam_odometry_node."""

import os
import subprocess
import sys
import tempfile
import time
import unittest

import rospkg
import rospy
import rostest
from std_srvs.srv import Trigger

from dslam.srv import SaveTrajectory

sys.path.insert(0, os.path.join(rospkg.RosPack().get_path("dslam"), "scripts"))
import test_scenes  # noqa: E402 (beside this file)
from frame_sender import Node, Sequence  # noqa: E402 (beside this file)
from rostest_helpers import is_identity, map_odom_transforms  # noqa: E402 (beside)
from dslam_tools import trajectory as traj  # noqa: E402

FRAMES = 60
STREAM = "/tmp/dslam_robustness_stream.txt"  # ~trajectory_stream in robustness.test
T0 = 1000.0


class RobustnessTest(unittest.TestCase):
    def test_cases_in_order(self):
        rospy.init_node("robustness_check")
        work = tempfile.mkdtemp(prefix="dslam_robustness_")
        folder, _ = test_scenes.scene("static_room", FRAMES, with_bag=True)  # as odometry_bag's
        seq, node = Sequence(folder), Node()
        rospy.wait_for_service("/dslam/save_trajectory", timeout=30.0)
        node.wait_connected()
        stamp = [T0 + i / 30.0 for i in range(FRAMES)]
        for i in range(20):
            self.assertNotEqual(node.send(seq.messages(i, stamp[i])).state, "rejected")
        self.check_skipped_sets(seq, node, stamp)
        self.check_reset_service(seq, node, stamp)
        self.check_gap_and_backwards(seq, node, stamp)
        self.check_map_odom(node, stamp)
        self.check_saved_segments(work, folder, node)
        self.check_missing_camera_info(seq, node)
        path_lengths = node.path_lengths()
        self.assertTrue(path_lengths and max(path_lengths) <= 5, path_lengths)
        self.check_path(node, stamp)
        self.check_invalid_parameter()

    def check_path(self, node, stamp):
        """Each path published is in stamp order (one run); the newest holds the newest base poses
        in `map` (map -> odom being the identity here: the odom poses of the same stamps), oldest
        first, all from the run that began when time went backwards (stamp[0] + 0.5)."""
        # Arrival order: a stamp sent twice (frame 15's, again when time went backwards) keeps
        # its newest pose.
        odom = {o.header.stamp.to_nsec(): o.pose.pose for o in node.rec.messages("odom")}
        # Every path published holds one run, oldest first: the path is emptied when time goes
        # backwards (a path still holding the old run's later stamps is out of order).
        for published in node.rec.messages("path"):
            in_order = [p.header.stamp.to_nsec() for p in published.poses]
            self.assertEqual(in_order, sorted(in_order), "a path mixes two runs")
        path = node.rec.last("path")
        self.assertEqual(path.header.frame_id, "map")
        stamps = [p.header.stamp.to_nsec() for p in path.poses]
        self.assertEqual(len(stamps), 5)
        self.assertEqual(stamps, sorted(stamps))
        self.assertEqual(stamps[-1], node.rec.last("odom").header.stamp.to_nsec())  # the newest
        self.assertGreaterEqual(stamps[0] * 1e-9, stamp[0] + 0.5 - 1e-6)
        for pose in path.poses:
            expected = odom[pose.header.stamp.to_nsec()]
            self.assertEqual(pose.header.frame_id, "map")
            got = (pose.pose.position.x, pose.pose.position.y, pose.pose.position.z)
            want = (expected.position.x, expected.position.y, expected.position.z)
            for a, b in zip(got, want):
                self.assertAlmostEqual(a, b, places=9)

    def check_skipped_sets(self, seq, node, stamp):
        zero = node.send(seq.messages(20, 0.0))
        self.assertEqual(zero.state, "rejected")
        self.assertIn("zero timestamp", zero.message)
        repeated = node.send(seq.messages(19, stamp[19]))
        self.assertEqual(repeated.state, "rejected")
        self.assertIn("repeated timestamp", repeated.message)
        bad = node.send(seq.messages(20, stamp[20] - 0.001, encoding="32SC4"))
        self.assertEqual(bad.state, "rejected")
        self.assertIn("32SC4", bad.message)
        self.assertGreaterEqual(bad.frames_rejected, 3)
        other = node.send(seq.messages(20, stamp[20], depth_frame="other_depth_frame"))
        self.assertNotEqual(other.state, "rejected")
        self.assertTrue(node.wait_logged("depth frame 'other_depth_frame'"), "no frame-id warning")

    def check_reset_service(self, seq, node, stamp):
        self.assertTrue(rospy.ServiceProxy("/dslam/reset", Trigger)().success)
        first = node.send(seq.messages(21, stamp[21]))
        self.assertTrue(first.reset)
        self.assertTrue(first.message.startswith("reset by the reset service"), first.message)
        self.assertFalse(first.has_pose)  # assumed at the last pose, not measured
        for i in range(22, 40):
            if i == 30:  # a dropped depth message: no set is formed, tracking goes on
                colour, _, info = seq.messages(i, stamp[i])
                node.send([colour, None, info], expect_status=False)
                continue
            status = node.send(seq.messages(i, stamp[i]))
            self.assertFalse(status.reset)
            self.assertTrue(status.has_pose, "frame %d: %s" % (i, status.message))

    def check_gap_and_backwards(self, seq, node, stamp):
        late = node.send(seq.messages(40, stamp[40] + 5.0))
        self.assertNotEqual(late.state, "rejected")
        self.assertTrue(node.wait_logged("s since the previous frame"), "no gap warning")
        back = node.send(seq.messages(41, stamp[0] + 0.5))
        self.assertTrue(back.reset)
        self.assertIn("time went backwards", back.message)
        self.assertTrue(back.has_pose)  # the first frame of a new run, at the origin
        for i in range(42, FRAMES):  # the new run tracks on
            status = node.send(seq.messages(i, stamp[0] + 0.5 + (i - 41) / 30.0))
            self.assertEqual(status.state, "tracking", "frame %d: %s" % (i, status.message))
            self.assertTrue(status.has_pose, "frame %d" % i)
            self.assertFalse(status.reset, "frame %d" % i)

    def check_map_odom(self, node, stamp):
        """Nothing corrected (no back end) and nothing jumped: map -> odom stays the identity
        through the reset service (the frame after the re-initialised one is tracked from it)
        and time going backwards, whose first frame puts odom back at the origin."""
        map_odom = map_odom_transforms(node.rec)
        self.assertGreaterEqual(len(map_odom), 30)
        self.assertTrue(all(is_identity(t.transform) for t in map_odom.values()))
        # The newest odometry with the stamp of the first frame back (frame 15 had it too).
        back = [o for o in node.rec.messages("odom")
                if abs(o.header.stamp.to_sec() - (stamp[0] + 0.5)) < 1e-6][-1]
        p = back.pose.pose.position
        self.assertEqual((p.x, p.y, p.z, back.pose.pose.orientation.w), (0.0, 0.0, 0.0, 1.0))

    def check_saved_segments(self, work, folder, node):
        out = os.path.join(work, "saved.txt")
        reply = rospy.ServiceProxy("/dslam/save_trajectory", SaveTrajectory)(out)
        self.assertTrue(reply.success, reply.message)
        older = traj.read_tum_positions(os.path.join(work, "saved.seg1.txt"))
        current = traj.read_tum_positions(out)
        self.assertEqual(reply.poses, len(older[0]) + len(current[0]))
        # Frames 0-40 but the rejected ones, the re-initialised frame 21 and the dropped frame 30;
        # the new run 41-59.
        self.assertEqual(len(older[0]), 39)
        self.assertEqual(len(current[0]), 19)
        # The reset service kept one world frame: the whole first segment against ground truth.
        ate_m = traj.evaluate(os.path.join(folder, "groundtruth.txt"),
                              os.path.join(work, "saved.seg1.txt"))["metrics"]["ate_rmse_m"]
        rospy.loginfo("robustness_check: first segment ATE %.4f m", ate_m)
        self.assertLess(ate_m, 0.03)
        # The stream holds the same poses as the saved files, as it goes.
        for saved, streamed in [(out, STREAM),
                                (os.path.join(work, "saved.seg1.txt"),
                                 STREAM.replace(".txt", ".seg1.txt"))]:
            with open(saved) as a, open(streamed) as b:
                self.assertEqual(a.read(), b.read())
        self.check_refined_segment(work, current)

    def check_refined_segment(self, work, current):
        """save_refined_trajectory writes the current segment alone (time went backwards at
        frame 41): the frames of save_trajectory's current file; the back end is off, so the
        poses are the tracked ones up to the files' decimals."""
        out = os.path.join(work, "refined.txt")
        reply = rospy.ServiceProxy("/dslam/save_refined_trajectory", SaveTrajectory)(out)
        self.assertTrue(reply.success, reply.message)
        stamps, positions = traj.read_tum_positions(out)
        self.assertEqual(reply.poses, len(stamps))
        self.assertEqual(list(stamps), list(current[0]))
        worst = abs(positions - current[1]).max()
        rospy.loginfo("robustness_check: refined segment %d poses, %.2g m from the tracked ones",
                      len(stamps), worst)
        self.assertLess(worst, 1e-5)

    def check_missing_camera_info(self, seq, node):
        colour, depth, _ = seq.messages(0, 5000.0)
        for k in range(25):  # 2.5 s of colour and depth without camera_info
            node.pubs[0].publish(colour)
            node.pubs[1].publish(depth)
            time.sleep(0.1)
        self.assertTrue(node.wait_logged("nothing on /camera/rgb/camera_info"),
                        "no warning about the missing camera_info")

    def check_invalid_parameter(self):
        run = subprocess.run(["rosrun", "dslam", "dslam_odometry_node", "__name:=bad_params",
                              "_queue_size:=0"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             timeout=60, universal_newlines=True)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("queue_size", run.stdout)
        # A transport without its plugin: refused at start naming the parameter (it crashed the
        # node in the nodelet's destruction after image_transport threw).
        run = subprocess.run(["rosrun", "dslam", "dslam_odometry_node", "__name:=bad_transport",
                              "_image_transport:=no_such_transport"], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, timeout=60, universal_newlines=True)
        self.assertEqual(run.returncode, 1, run.stdout)
        self.assertIn("~image_transport 'no_such_transport' has no plugin", run.stdout)


if __name__ == "__main__":
    rostest.rosrun("dslam", "robustness", RobustnessTest)
