#!/usr/bin/env python3
"""rostest (keyframe_map_start.test): what docs/ros-interface.md promises about starting in a
keyframe map, on nodes this script launches (dslam.launch, exact sync) and feeds frame by frame
with frames of a rendered static_room sequence:
1. a corrupt ~keyframe_map is refused with its reason and the node maps from scratch;
   save_keyframe_map before the first frame answers false ("no frame yet"); at shutdown
   ~save_keyframe_map_on_exit writes the map and keeps the file that was there as PATH.prev;
2. a node started in that map localises ("localising", then tracking in the map's world); the
   reset service and time going backwards start it in the loaded map again ("localising");
3. a node whose camera differs from the map's refuses the map at its first frame, says why and
   maps from scratch;
4. frames that cannot be localised until ~localise_timeout_s has passed: the next frame starts a
   new map at the origin, with a warning."""

import os
import struct
import sys
import tempfile
import unittest

import rospkg
import rospy
import rostest
from std_srvs.srv import Trigger

from dslam.srv import SaveKeyFrameMap

sys.path.insert(0, os.path.join(rospkg.RosPack().get_path("dslam"), "scripts"))
import test_scenes  # noqa: E402 (beside this file)
from frame_sender import Sequence, start_node, stop  # noqa: E402 (beside this file)

FRAMES = 60
T0 = 1000.0
OLDER = b"the file that was at the exit path"


def header(path):
    """(magic, version, size in the header, file size, keyframes) of a keyframe map file
    (include/dslam/map_file/keyframe_map_file.h)."""
    with open(path, "rb") as handle:
        data = handle.read()
    magic, version, size, _ = struct.unpack_from("<8sIQQ", data, 0)
    _, _, keyframes, _ = struct.unpack_from("<QIII", data, 108)
    return magic, version, size, len(data), keyframes


class KeyFrameMapStartTest(unittest.TestCase):
    def test_in_order(self):
        rospy.init_node("keyframe_map_start_check")
        work = tempfile.mkdtemp(prefix="dslam_kfm_start_")
        folder, _ = test_scenes.scene("static_room", FRAMES, with_bag=True)  # as odometry_bag's
        seq = Sequence(folder)
        saved = self.check_refused_then_saved_on_exit(work, seq)
        self.check_reset_and_backwards_in_the_loaded_map(work, seq, saved)
        self.check_other_camera_refused(work, seq, saved)
        self.check_localise_timeout(work, seq, saved)

    def start(self, work, ns, keyframe_map, on_exit="", timeout_s=10.0):
        return start_node(work, ns, {"keyframe_map": keyframe_map},
                          {"save_keyframe_map_on_exit": on_exit, "localise_timeout_s": timeout_s})

    def check_refused_then_saved_on_exit(self, work, seq):
        corrupt = os.path.join(work, "corrupt.kfm")
        with open(corrupt, "wb") as out:
            out.write(b"DSLAMKFM" + bytes(200))
        on_exit = os.path.join(work, "on_exit.kfm")
        with open(on_exit, "wb") as out:
            out.write(OLDER)
        process, node = self.start(work, "dslam_corrupt", corrupt, on_exit)
        try:
            self.assertTrue(node.wait_logged("keyframe map refused, mapping from scratch"))
            refusal = [log.msg for log in node.rec.messages("log") if "refused" in log.msg][0]
            rospy.loginfo("keyframe_map_start_check: %s", refusal)
            self.assertIn(corrupt, refusal)  # the reason names the file
            early = rospy.ServiceProxy("/dslam_corrupt/save_keyframe_map", SaveKeyFrameMap)(
                os.path.join(work, "early.kfm"))
            self.assertFalse(early.success)
            self.assertIn("no frame yet", early.message)
            states = [node.send(seq.messages(i, T0 + i / 30.0)).state for i in range(30)]
            self.assertEqual(states, ["initialised"] + ["tracking"] * 29)  # from scratch
        finally:
            stop(process)
        magic, version, size, length, keyframes = header(on_exit)
        self.assertEqual((magic, version, size), (b"DSLAMKFM", 2, length))
        self.assertGreater(keyframes, 1)
        with open(on_exit + ".prev", "rb") as handle:
            self.assertEqual(handle.read(), OLDER)
        self.assertFalse([f for f in os.listdir(work) if ".tmp-" in f])
        return on_exit

    def check_reset_and_backwards_in_the_loaded_map(self, work, seq, saved):
        process, node = self.start(work, "dslam_loaded", saved)
        try:
            first = node.send(seq.messages(30, T0 + 1.0))
            # The first frame of frames 30-59 is relocalised at once (keyframe_map.test: at
            # the first frame), so the node never starts a map of its own.
            self.assertIn(first.state, ("localising", "tracking", "recovered"))
            states = [node.send(seq.messages(i, T0 + i / 30.0)).state for i in range(31, 40)]
            self.assertNotIn("initialised", states)
            self.assertEqual(states[-1], "tracking")
            self.assertTrue(rospy.ServiceProxy("/dslam_loaded/reset", Trigger)().success)
            after_reset = node.send(seq.messages(40, T0 + 40 / 30.0))
            self.assertTrue(after_reset.reset)
            # In the loaded map again: the frame is relocalised in it at once ("recovered") or
            # waits for one that is; never a map of its own ("initialised").
            self.assertTrue(after_reset.message.startswith(
                "reset by the reset service: localising in the loaded keyframe map"),
                after_reset.message)
            self.assertIn(after_reset.state, ("localising", "recovered"))
            states = [node.send(seq.messages(i, T0 + i / 30.0)).state for i in range(41, 50)]
            self.assertNotIn("initialised", states)
            self.assertEqual(states[-1], "tracking")
            back = node.send(seq.messages(50, T0 + 0.5))
            self.assertTrue(back.reset)
            self.assertIn("time went backwards", back.message)
            self.assertIn(back.state, ("localising", "recovered"), back.message)
            states = [node.send(seq.messages(i, T0 + 0.5 + (i - 50) / 30.0)).state
                      for i in range(51, 55)]
            self.assertEqual(states, ["tracking"] * 4)
        finally:
            stop(process)

    def check_other_camera_refused(self, work, seq, saved):
        process, node = self.start(work, "dslam_other", saved)
        try:
            colour, depth, info = seq.messages(0, T0)
            info.K = list(info.K)
            info.K[0] += 20.0  # fx: another camera than the map's
            info.P = list(info.P)
            info.P[0] += 20.0
            status = node.send([colour, depth, info])
            self.assertEqual(status.state, "initialised", status.message)  # from scratch
            text = "keyframe map %s refused, mapping from scratch" % saved
            self.assertTrue(node.wait_logged(text))
            refusal = [log.msg for log in node.rec.messages("log") if text in log.msg][0]
            rospy.loginfo("keyframe_map_start_check: %s", refusal)
            self.assertIn("camera", refusal)
        finally:
            stop(process)

    def check_localise_timeout(self, work, seq, saved):
        """Frames that cannot be localised (black, no depth) until ~localise_timeout_s of stamps
        has passed: the next frame starts a new map at the origin, with a warning."""
        process, node = self.start(work, "dslam_timeout", saved, timeout_s=0.5)
        try:
            for i in range(3):
                colour, depth, info = seq.messages(i, T0 + i / 30.0)
                colour.data = bytes(len(colour.data))
                depth.data = bytes(len(depth.data))
                status = node.send([colour, depth, info])
                self.assertIn(status.state, ("localising", "lost"), status.message)  # no features
                self.assertFalse(status.has_pose)
            late = node.send(seq.messages(20, T0 + 0.6))  # 0.6 s after the first frame
            self.assertTrue(late.reset)
            self.assertEqual(late.state, "initialised", late.message)
            self.assertIn("not localised in the loaded keyframe map within", late.message)
            self.assertTrue(late.has_pose)
            self.assertTrue(node.wait_logged("not localised in the loaded keyframe map"))
            self.assertEqual(node.send(seq.messages(21, T0 + 0.6 + 1 / 30.0)).state, "tracking")
        finally:
            stop(process)


if __name__ == "__main__":
    rostest.rosrun("dslam", "keyframe_map_start_check", KeyFrameMapStartTest)
