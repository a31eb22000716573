#!/usr/bin/env python3
"""rostest: a stand-in for openni2_launch publishes camera/rgb/image_raw (rgb8),
camera/depth_registered/image_raw (16UC1 millimetres) and camera/rgb/camera_info (the raw pair
openni2.launch subscribes to by default); checks that openni2.launch's remapping delivers them to
dslam (status and odometry arrive, frames tracked)."""

import unittest

import numpy as np
import rospy
import rostest
from nav_msgs.msg import Odometry
from sensor_msgs.msg import CameraInfo, Image

from dslam.msg import FrameStatus

from rostest_helpers import Recorder  # beside this file

WIDTH, HEIGHT, FX = 640, 480, 525.0


def textured_scene():
    """A seeded random texture (blocks of grey levels) on a wall 2 m away."""
    rng = np.random.RandomState(7)
    blocks = rng.randint(0, 256, size=(HEIGHT // 8, WIDTH // 8, 3)).astype(np.uint8)
    colour = np.kron(blocks, np.ones((8, 8, 1), dtype=np.uint8))
    depth = np.full((HEIGHT, WIDTH), 2000, dtype=np.uint16)
    depth[:, :40] = 0  # a band without depth, as near image borders of real sensors
    return colour, depth


def image(pixels, encoding, stamp):
    msg = Image()
    msg.header.stamp, msg.header.frame_id = stamp, "camera_rgb_optical_frame"
    msg.height, msg.width = pixels.shape[:2]
    msg.encoding, msg.is_bigendian = encoding, 0
    msg.step = pixels.strides[0]
    msg.data = pixels.tobytes()
    return msg


def camera_info(stamp):
    msg = CameraInfo()
    msg.header.stamp, msg.header.frame_id = stamp, "camera_rgb_optical_frame"
    msg.width, msg.height, msg.distortion_model = WIDTH, HEIGHT, "plumb_bob"
    msg.D = [0.0] * 5
    msg.K = [FX, 0, WIDTH / 2.0 - 0.5, 0, FX, HEIGHT / 2.0 - 0.5, 0, 0, 1]
    msg.R = [1, 0, 0, 0, 1, 0, 0, 0, 1]
    msg.P = [FX, 0, WIDTH / 2.0 - 0.5, 0, 0, FX, HEIGHT / 2.0 - 0.5, 0, 0, 0, 1, 0]
    return msg


class OpenNI2RemapTest(unittest.TestCase):
    def test_standin_topics_reach_dslam(self):
        rospy.init_node("openni2_standin_check")
        rec = Recorder()
        rec.subscribe("/dslam/status", FrameStatus, "status", queue_size=None)
        rec.subscribe("/dslam/odom", Odometry, "odom", queue_size=None)
        pubs = [rospy.Publisher("/camera/rgb/image_raw", Image, queue_size=5),
                rospy.Publisher("/camera/depth_registered/image_raw", Image, queue_size=5),
                rospy.Publisher("/camera/rgb/camera_info", CameraInfo, queue_size=5)]
        colour, depth = textured_scene()
        deadline = rospy.Time.now() + rospy.Duration(30.0)
        rate = rospy.Rate(10)
        while rospy.Time.now() < deadline and not rospy.is_shutdown():
            stamp = rospy.Time.now()
            for pub, msg in zip(pubs, [image(colour, "rgb8", stamp), image(depth, "16UC1", stamp),
                                       camera_info(stamp)]):
                pub.publish(msg)
            if rec.count("odom") >= 5:
                break
            rate.sleep()
        self.assertGreaterEqual(rec.count("odom"), 5, "no odometry from the stand-in")
        status = rec.last("status")
        odom = rec.last("odom")
        self.assertEqual(status.frames_rejected, 0)
        self.assertIn(status.state, ["initialised", "tracking", "recovered"])
        self.assertEqual(odom.child_frame_id, "camera_link")
        # The camera does not move: the pose stays at the origin.
        p = odom.pose.pose.position
        self.assertLess(abs(p.x) + abs(p.y) + abs(p.z), 0.02)


if __name__ == "__main__":
    rostest.rosrun("dslam", "openni2_remap", OpenNI2RemapTest)
