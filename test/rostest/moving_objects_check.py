#!/usr/bin/env python3
"""rostest: plays a synthetic bag of two walkers (dslam_synth `walking`) into the dslam nodelet and
checks `moving_objects` (dslam/MovingObjects) and `moving_object_markers` (MarkerArray): messages
in the map frame (the tracker's world, ~publish_map_tf true) with the images' stamps, walkers
found in most frames, plausible sizes and speeds, ids that persist across frames, and a box, an
arrow and a label per reported object; and `obstacles` (PointCloud2, the people's points of each
frame): in the map frame, points in most frames, and in each frame with objects its points lie
within the objects' boxes (grown by 0.3 m) for the most part."""

import collections
import unittest

import rospy
import rostest
from sensor_msgs import point_cloud2
from sensor_msgs.msg import PointCloud2
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
        rec.subscribe("/dslam/obstacles", PointCloud2, "obstacles", queue_size=200)
        play_bag(bag, recorder=rec)
        self.check_objects(rec.messages("objects"))
        self.check_markers(rec.messages("markers"))
        self.check_obstacles(rec.messages("obstacles"), rec.messages("objects"))

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

    def check_obstacles(self, clouds, objects):
        self.assertGreater(len(clouds), FRAMES // 2)
        self.assertTrue(all(c.header.frame_id == "map" for c in clouds))
        points = {c.header.stamp.to_nsec(): list(point_cloud2.read_points(
            c, field_names=("x", "y", "z"), skip_nans=True)) for c in clouds}
        self.assertGreater(sum(1 for p in points.values() if p), len(clouds) // 2)
        inside_shares = []
        for m in objects:
            cloud = points.get(m.header.stamp.to_nsec())
            if not m.objects or not cloud:
                continue
            inside = 0
            for x, y, z in cloud:
                for o in m.objects:
                    c, e = o.position, o.extent
                    if (abs(x - c.x) <= e.x / 2 + 0.3 and abs(y - c.y) <= e.y / 2 + 0.3 and
                            abs(z - c.z) <= e.z / 2 + 0.3):
                        inside += 1
                        break
            inside_shares.append(inside / len(cloud))
        rospy.loginfo("moving_objects_check: %d obstacle clouds, %d with points, median share "
                      "inside the objects' boxes %.3f", len(clouds),
                      sum(1 for p in points.values() if p),
                      sorted(inside_shares)[len(inside_shares) // 2] if inside_shares else -1)
        self.assertGreater(len(inside_shares), 20)
        self.assertGreater(sorted(inside_shares)[len(inside_shares) // 2], 0.8)

    def check_markers(self, arrays):
        self.assertGreater(len(arrays), FRAMES // 2)
        for array in arrays:
            self.assertEqual(array.markers[0].action, Marker.DELETEALL)
            types = collections.Counter(m.type for m in array.markers[1:])
            self.assertEqual(types[Marker.CUBE], types[Marker.ARROW])
            self.assertEqual(types[Marker.CUBE], types[Marker.TEXT_VIEW_FACING])


if __name__ == "__main__":
    rostest.rosrun("dslam", "moving_objects", MovingObjectsTest)
