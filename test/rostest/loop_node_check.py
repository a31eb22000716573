#!/usr/bin/env python3
"""rostest (loop_node.test): a loop closed in the node. The synthetic room_tour bag (the camera
carried once round the room and into its first views again, two walkers) is played into the node
of the launch file (back end and loop closing on, exact sync; at half speed): `status` counts the loop
(`loop_closures`), `loop_edges` draws it in the map frame, the loop's correction goes into
map -> odom while odom stays continuous (no step larger than the camera's motion), and the
refined trajectory ends near the ground truth."""

import os
import sys
import tempfile
import unittest

import numpy as np
import rospkg
import rospy
import rostest
from nav_msgs.msg import Odometry
from tf2_msgs.msg import TFMessage
from visualization_msgs.msg import Marker, MarkerArray

from dslam.msg import FrameStatus
from dslam.srv import SaveTrajectory

sys.path.insert(0, os.path.join(rospkg.RosPack().get_path("dslam"), "scripts"))
from dslam_tools import trajectory as traj  # noqa: E402
import test_scenes  # noqa: E402 (beside this file)
from rostest_helpers import Recorder, map_odom_transforms, play_bag  # noqa: E402 (beside)

FRAMES = 728  # the scenario's default: a lap and 6 s into its first views again
# The camera moves at 0.45 m/s (15 mm a frame at 30 Hz): a larger step of odom is a jump.
MAX_ODOM_STEP_M = 0.03


def position(pose):
    return np.array([pose.position.x, pose.position.y, pose.position.z])


class LoopNodeTest(unittest.TestCase):
    def test_a_loop_closes_in_the_node(self):
        rospy.init_node("loop_node_check")
        work = tempfile.mkdtemp(prefix="dslam_loop_node_")
        folder, bag = test_scenes.scene("room_tour", FRAMES, with_bag=True)
        rec = Recorder()
        rec.subscribe("/dslam/status", FrameStatus, "status", queue_size=1000)
        rec.subscribe("/dslam/odom", Odometry, "odom", queue_size=1000)
        rec.subscribe("/dslam/loop_edges", MarkerArray, "loop_edges")
        rec.subscribe("/tf", TFMessage, "tf", queue_size=1000)
        play_bag(bag, rate=0.5, settle_s=5.0, recorder=rec)
        statuses = rec.messages("status")
        loops = statuses[-1].loop_closures
        rospy.loginfo("loop_node_check: %d frames processed, %d loops", len(statuses), loops)
        self.assertGreaterEqual(len(statuses), FRAMES * 0.9)  # a busy machine may drop a few
        self.assertGreaterEqual(loops, 1)
        self.check_loop_edges(rec, loops)
        self.check_correction_in_map_odom(rec, statuses)
        out = os.path.join(work, "refined.txt")
        reply = rospy.ServiceProxy("/dslam/save_refined_trajectory", SaveTrajectory)(out)
        self.assertTrue(reply.success, reply.message)
        ate = traj.evaluate(os.path.join(folder, "groundtruth.txt"), out)["metrics"]["ate_rmse_m"]
        rospy.loginfo("loop_node_check: refined ATE %.4f m", ate)
        self.assertLess(ate, 0.09)  # measured 0.0455 m

    def check_loop_edges(self, rec, loops):
        """The latest loop_edges: one LINE_LIST in map with a line (two points) per loop."""
        markers = [m for m in rec.last("loop_edges").markers if m.action == Marker.ADD]
        self.assertEqual(len(markers), 1)
        self.assertEqual(markers[0].type, Marker.LINE_LIST)
        self.assertEqual(markers[0].header.frame_id, "map")
        self.assertEqual(len(markers[0].points), 2 * loops)

    def check_correction_in_map_odom(self, rec, statuses):
        """The loop's correction goes into map -> odom, not odom: where map -> odom moves most
        from one frame to the next (after the first loop), odom moves no more than the camera."""
        first = next(s for s in statuses if s.loop_closures > 0).header.stamp.to_nsec()
        map_odom = map_odom_transforms(rec)
        odom = {o.header.stamp.to_nsec(): position(o.pose.pose) for o in rec.messages("odom")}
        stamps = [s for s in sorted(map_odom) if s in odom]

        def translation(stamp):
            t = map_odom[stamp].transform.translation
            return np.array([t.x, t.y, t.z])
        # The status reports a loop at the next keyframe or within a second of its correction.
        jumps = [(np.linalg.norm(translation(b) - translation(a)), a, b)
                 for a, b in zip(stamps, stamps[1:]) if first - int(2e9) <= b <= first]
        jump, a, b = max(jumps)
        frames = max(1, round((b - a) * 30e-9))  # stamps apart (a busy node may skip one)
        step = np.linalg.norm(odom[b] - odom[a]) / frames
        rospy.loginfo("loop_node_check: map -> odom jumped %.4f m at %.3f s (first loop reported at "
                      "%.3f s); odom moved %.4f m a frame there", jump, b * 1e-9, first * 1e-9, step)
        self.assertGreater(jump, 0.05)
        self.assertLess(step, MAX_ODOM_STEP_M)


if __name__ == "__main__":
    rostest.rosrun("dslam", "loop_node_check", LoopNodeTest)
