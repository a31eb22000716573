#!/usr/bin/env python3
"""rostest: plays a synthetic bag of two walkers (dslam_synth `walking`) into the dslam nodelet and
checks `moving_objects` (dslam/MovingObjects) and `moving_object_markers` (MarkerArray): messages
in the map frame (the tracker's world, ~publish_map_tf true) with the images' stamps, walkers
found in most frames, plausible sizes and speeds, ids that persist across frames, and a box, an
arrow and a label per reported object."""

import collections
import unittest

import rospy
import rostest
from visualization_msgs.msg import Marker, MarkerArray

from dslam.msg import MovingObjects

import test_scenes  # beside this file
from rostest_helpers import Recorder, play_bag  # beside this file

FRAMES = 90


class MovingObjectsTest(unittest.TestCase):
    def test_objects_and_markers(self):
        rospy.init_node("moving_objects_check")
        folder, bag = test_scenes.scene("walking", FRAMES, with_bag=True)
        rec = Recorder()
        rec.subscribe("/dslam/moving_objects", MovingObjects, "objects", queue_size=200)
        rec.subscribe("/dslam/moving_object_markers", MarkerArray, "markers", queue_size=200)
        play_bag(bag, recorder=rec)
        self.check_objects(rec.messages("objects"))
        self.check_markers(rec.messages("markers"))

    def check_objects(self, messages):
        self.assertGreater(len(messages), FRAMES // 2)
        self.assertTrue(all(m.header.frame_id == "map" for m in messages))
        with_objects = [m for m in messages if m.objects]
        frames_by_id = collections.Counter(o.id for m in messages for o in m.objects)
        rospy.loginfo("moving_objects_check: %d messages, %d with objects, ids %s",
                      len(messages), len(with_objects), dict(frames_by_id))
        # Two walkers cover much of the view from the first frames on.
        self.assertGreater(len(with_objects), len(messages) // 2)
        self.assertGreaterEqual(max(frames_by_id.values()), 20, "no id persists")
        for m in with_objects:
            for o in m.objects:
                self.assertGreater(min(o.extent.x, o.extent.y, o.extent.z), 0.0)
                self.assertLess(max(o.extent.x, o.extent.y, o.extent.z), 4.0)
                speed = (o.velocity.x ** 2 + o.velocity.y ** 2 + o.velocity.z ** 2) ** 0.5
                self.assertLess(speed, 5.0)  # walkers: about 1 m/s
                self.assertGreaterEqual(o.age_s, 0.0)

    def check_markers(self, arrays):
        self.assertGreater(len(arrays), FRAMES // 2)
        for array in arrays:
            self.assertEqual(array.markers[0].action, Marker.DELETEALL)
            types = collections.Counter(m.type for m in array.markers[1:])
            self.assertEqual(types[Marker.CUBE], types[Marker.ARROW])
            self.assertEqual(types[Marker.CUBE], types[Marker.TEXT_VIEW_FACING])


if __name__ == "__main__":
    rostest.rosrun("dslam", "moving_objects", MovingObjectsTest)
