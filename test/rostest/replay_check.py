#!/usr/bin/env python3
"""rostest: renders 10 frames of static_room (dslam_synth), runs dslam_replay on them at 30 Hz for
2 s with 16UC1 depth (60 frames, 6 loops) and checks what arrives on /camera/*: 60 messages per
topic, stamps of colour, depth and camera_info equal per frame and strictly increasing by 1/30 s
(across loops), arrival spread close to 59/30 s, the encodings, the intrinsics of camera.yaml,
frame k + 10 carrying the pixels of frame k (looping), and the replay's own count."""

import subprocess
import unittest

import rospy
import rostest
from sensor_msgs.msg import CameraInfo, Image

import test_scenes  # beside this file
from rostest_helpers import Recorder  # beside this file

FRAMES = 10
RATE_HZ = 30.0
DURATION_S = 2.0
EXPECTED = int(RATE_HZ * DURATION_S)


class ReplayTest(unittest.TestCase):
    def test_replay(self):
        rospy.init_node("replay_check")
        folder, _ = test_scenes.scene("static_room", FRAMES)
        rec = Recorder()
        subs = [rec.subscribe("/camera/rgb/image", Image, "rgb"),
                rec.subscribe("/camera/depth/image", Image, "depth"),
                rec.subscribe("/camera/rgb/camera_info", CameraInfo, "info")]
        out = subprocess.run(["rosrun", "dslam", "dslam_replay", "--dataset", folder, "--rate",
                              str(RATE_HZ), "--duration", str(DURATION_S), "--depth", "16UC1",
                              "__ns:=/camera"], check=True, stdout=subprocess.PIPE, text=True,
                             timeout=60).stdout
        rospy.sleep(1.0)
        for sub in subs:
            sub.unregister()
        self.assertRegex(out, r"published %d frames" % EXPECTED)
        msgs = {name: rec.timed(name) for name in ["rgb", "depth", "info"]}
        for name, received in msgs.items():
            self.assertEqual(len(received), EXPECTED, name)
        rgb = [m for _, m in msgs["rgb"]]
        depth = [m for _, m in msgs["depth"]]
        info = [m for _, m in msgs["info"]]
        for k in range(EXPECTED):
            self.assertEqual(rgb[k].header.stamp, depth[k].header.stamp)
            self.assertEqual(rgb[k].header.stamp, info[k].header.stamp)
        steps = [(b.header.stamp - a.header.stamp).to_sec() for a, b in zip(rgb, rgb[1:])]
        self.assertTrue(all(abs(s - 1.0 / RATE_HZ) < 1e-6 for s in steps), steps)
        spread = msgs["rgb"][-1][0] - msgs["rgb"][0][0]
        rospy.loginfo("replay_check: %d frames arrived over %.3f s", EXPECTED, spread)
        self.assertAlmostEqual(spread, (EXPECTED - 1) / RATE_HZ, delta=0.25)
        self.assertEqual(rgb[0].encoding, "bgr8")
        self.assertEqual(depth[0].encoding, "16UC1")
        self.assertEqual((rgb[0].width, rgb[0].height), (640, 480))
        self.assertEqual(list(info[0].K), [525.0, 0.0, 319.5, 0.0, 525.0, 239.5, 0.0, 0.0, 1.0])
        self.assertEqual(rgb[3].data, rgb[3 + FRAMES].data)
        self.assertEqual(depth[3].data, depth[3 + 2 * FRAMES].data)
        self.assertNotEqual(rgb[3].data, rgb[4].data)


if __name__ == "__main__":
    rostest.rosrun("dslam", "replay", ReplayTest)
