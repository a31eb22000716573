#!/usr/bin/env python3
"""rostest (keyframe_map.test): the node of the launch file maps frames 0-29 of a synthetic
static_room bag and saves its keyframe map with save_keyframe_map (refused for a path it cannot
write); a second node started with ~keyframe_map on that file gets frames 30-59: its status says
"localising" until a frame is relocalised in the loaded map, after which its saved poses are in
the first node's world (the first frame's camera), near the ground truth expressed there without
any alignment, and its map extends the loaded one. A third node with ~localisation_only gets the
same frames: it never starts a map of its own, and its save_keyframe_map writes the loaded file
byte for byte; without ~keyframe_map, ~localisation_only stops the node at start with an error
naming it."""

import os
import signal
import subprocess
import sys
import tempfile
import unittest

import numpy as np
import rospkg
import rospy
import rostest

from dslam.msg import FrameStatus
from dslam.srv import SaveKeyFrameMap, SaveTrajectory

sys.path.insert(0, os.path.join(rospkg.RosPack().get_path("dslam"), "scripts"))
import test_scenes  # noqa: E402 (beside this file)
from rostest_helpers import Recorder, play_bag, tum_matrix  # noqa: E402

FRAMES = 60
# static_room moves 0.2-0.3 m from frame 0 by frames 30-59: a node in its own world would be that
# far off; measured here (e841b8d): localised at the first frame, worst error 0.0033 m
POSITION_TOLERANCE_M = 0.007
MAX_LOCALISING_FRAMES = 10  # the bound is 30 frames on real data


class KeyFrameMapTest(unittest.TestCase):
    def test_save_then_localise_in_a_second_node(self):
        rospy.init_node("keyframe_map_check")
        work = tempfile.mkdtemp(prefix="dslam_rostest_")
        folder, bag = test_scenes.scene("static_room", FRAMES, with_bag=True)
        play_bag(bag, options=["-u", "0.99"])  # frames 0-29 (30 Hz)
        saved = os.path.join(work, "room.kfm")
        save = rospy.ServiceProxy("/dslam/save_keyframe_map", SaveKeyFrameMap)
        refused = save(os.path.join(work, "missing", "folder", "room.kfm"))
        self.assertFalse(refused.success)
        self.assertIn(os.path.join(work, "missing", "folder"), refused.message)
        result = save(saved)
        self.assertTrue(result.success, result.message)
        self.assertGreater(result.keyframes, 1)
        rospy.loginfo("keyframe_map_check: %s", result.message)
        nodes = [subprocess.Popen(["roslaunch", "dslam", "dslam.launch", "ns:=" + ns,
                                   "manager:=" + ns + "_manager", "keyframe_map:=" + saved,
                                   "localisation_only:=" + only])
                 for ns, only in (("dslam_loaded", "false"), ("dslam_only", "true"))]
        try:
            rec = Recorder()
            rec.subscribe("/dslam_only/status", FrameStatus, "only_status")
            rospy.wait_for_service("/dslam_only/save_trajectory", timeout=30.0)
            self.check_second_node(folder, bag, work, result.keyframes)
            self.check_localisation_only_node(rec, work, saved)
        finally:
            for node in nodes:
                node.send_signal(signal.SIGINT)
            for node in nodes:
                node.wait(timeout=30)

    def check_localisation_only_node(self, rec, work, saved):
        states = [s.state for s in rec.messages("only_status")]
        rospy.loginfo("keyframe_map_check: localisation only: states %s", states)
        self.assertIn("tracking", states)
        self.assertNotIn("initialised", states, "the localisation-only node started a map")
        path = os.path.join(work, "only.kfm")
        result = rospy.ServiceProxy("/dslam_only/save_keyframe_map", SaveKeyFrameMap)(path)
        self.assertTrue(result.success, result.message)
        self.assertTrue(result.message.startswith("localisation only: the loaded map unchanged"),
                        result.message)
        with open(saved, "rb") as loaded, open(path, "rb") as written:
            self.assertEqual(loaded.read(), written.read())

    def check_second_node(self, folder, bag, work, saved_keyframes):
        rec = Recorder()
        rec.subscribe("/dslam_loaded/status", FrameStatus, "status")
        play_bag(bag, node="/dslam_loaded", options=["-s", "1.0"], recorder=rec)  # frames 30-59

        def accounted(r):  # a status per processed frame, the dropped ones counted in the last
            statuses = r.messages("status")
            return statuses and len(statuses) + statuses[-1].frames_dropped >= FRAMES // 2
        # The first frame starts the loaded map and relocalises: the worker may still be busy
        # with the backlog after play_bag's settle time (CI saw 19 of 30 statuses then).
        rec.wait_for(accounted)
        states = [s.state for s in rec.messages("status")]
        # Every set of frames 30-59 is processed or, while the worker is busy (the first frame
        # starts the loaded map and relocalises), dropped and counted: exact either way.
        dropped = rec.messages("status")[-1].frames_dropped
        self.assertEqual(len(states) + dropped, FRAMES // 2,
                         "the second node's status per frame 30-59")
        self.assertLessEqual(dropped, 2)
        localising = states.index(next(s for s in states if s != "localising"))
        rospy.loginfo("keyframe_map_check: states %s", states)
        self.assertLessEqual(localising, MAX_LOCALISING_FRAMES)
        self.assertNotIn("initialised", states, "the second node started a map of its own")
        path = os.path.join(work, "second.txt")
        result = rospy.ServiceProxy("/dslam_loaded/save_trajectory", SaveTrajectory)(path)
        self.assertTrue(result.success, result.message)
        self.assertEqual(result.poses, len(states) - localising)  # every frame after it
        truth = {"%.6f" % row[0]: tum_matrix(row) for row in
                 np.loadtxt(os.path.join(folder, "groundtruth.txt"), comments="#", ndmin=2)}
        first_stamp = min(truth)
        T_world_truth = np.linalg.inv(truth[first_stamp])  # the first node's world: frame 0
        worst = 0.0
        for row in np.loadtxt(path, comments="#", ndmin=2):
            expected = T_world_truth @ truth["%.6f" % row[0]]
            worst = max(worst, np.linalg.norm(tum_matrix(row)[:3, 3] - expected[:3, 3]))
        rospy.loginfo("keyframe_map_check: %d poses, worst position error %.4f m", result.poses,
                      worst)
        self.assertLess(worst, POSITION_TOLERANCE_M)
        extended = rospy.ServiceProxy("/dslam_loaded/save_keyframe_map", SaveKeyFrameMap)(
            os.path.join(work, "extended.kfm"))
        self.assertTrue(extended.success, extended.message)
        rospy.loginfo("keyframe_map_check: extended map %s", extended.message)
        self.assertGreater(extended.keyframes, saved_keyframes)  # the new views were added

    def test_localisation_only_without_a_map_is_refused(self):
        run = subprocess.run(["rosrun", "dslam", "dslam_odometry_node", "__name:=only_no_map",
                              "_localisation_only:=true"], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, timeout=60, universal_newlines=True)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("~localisation_only is true but ~keyframe_map is empty", run.stdout)


if __name__ == "__main__":
    rostest.rosrun("dslam", "keyframe_map_check", KeyFrameMapTest)
