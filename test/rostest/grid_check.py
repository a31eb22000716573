#!/usr/bin/env python3
"""rostest: plays a synthetic bag of two walkers (dslam_synth `walking`, 90 frames) into the dslam
nodelet and checks the occupancy grid: `grid` (nav_msgs/OccupancyGrid, latched, in the map frame)
arrives with occupied and free cells, equals the files `save_grid` writes (map_server's YAML with
dslam's keys and the PGM), `save_octomap` writes an OctoMap binary file, the first camera's cell
is free, and the cells of the walkers' path
(the truth's objects.txt: each walker's visible centroid in every frame) are free, not occupied:
their pixels are never fused and rays pass where they stood."""

import os
import sys
import tempfile
import unittest

import numpy as np
import rospy
import rostest
from nav_msgs.msg import OccupancyGrid

from dslam.srv import SaveGrid, SaveMap

import test_scenes  # beside this file
from rostest_helpers import Recorder, play_bag, tum_matrix  # beside this file

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..",
                                "scripts"))
from dslam_tools import grid_files  # noqa: E402
from dslam_tools.grid_files import numbers  # noqa: E402

FRAMES = 90
# Measured on these frames offline (dslam_run_dataset --grid, the same defaults): 8 of the 89
# path cells occupied (0.09), 81 free; the bounds leave twice the occupied share.
PATH_OCCUPIED_MAX = 0.18
PATH_FREE_MIN = 0.8


def path_cells(folder, keys):
    """The grid cells (i, j) of the walkers' visible centroids (objects.txt, truth world), placed
    in the first frame's optical frame by the first ground-truth pose, then in the grid frame."""
    first = np.loadtxt(os.path.join(folder, "groundtruth.txt"))[0]
    T_world0 = tum_matrix(first)
    T_grid_truth = np.linalg.inv(grid_files.world_grid_matrix(keys)) @ np.linalg.inv(T_world0)
    objects = np.loadtxt(os.path.join(folder, "objects.txt"))
    p = np.c_[objects[:, 2:5], np.ones(len(objects))] @ T_grid_truth.T
    s, origin = float(keys["resolution"]), numbers(keys["origin"])
    return {(int(np.floor((q[0] - origin[0]) / s)), int(np.floor((q[1] - origin[1]) / s)))
            for q in p}


class GridTest(unittest.TestCase):
    def test_grid_topic_files_and_walkers_path(self):
        rospy.init_node("grid_check")
        folder, bag = test_scenes.scene("walking", FRAMES, with_bag=True)
        rec = Recorder()
        rec.subscribe("/dslam/grid", OccupancyGrid, "grid", queue_size=10)
        play_bag(bag, recorder=rec, settle_s=3.0)  # the grid is rebuilt at 1 Hz after a change
        message = rec.last("grid")
        self.assertEqual(message.header.frame_id, "map")
        data = np.array(message.data, dtype=np.int8).reshape(message.info.height,
                                                             message.info.width)
        late = rospy.wait_for_message("/dslam/grid", OccupancyGrid, timeout=5.0)  # latched
        self.assertEqual(late.data, message.data)

        rospy.wait_for_service("/dslam/save_grid", timeout=10.0)
        path = os.path.join(tempfile.mkdtemp(prefix="dslam_grid_check_"), "grid.yaml")
        reply = rospy.ServiceProxy("/dslam/save_grid", SaveGrid)(path)
        self.assertTrue(reply.success, reply.message)
        keys, pixels = grid_files.read_grid(path)
        cells = grid_files.cells(pixels)
        rospy.loginfo("grid_check: %s", reply.message)
        self.assertEqual(cells.shape, data.shape)
        np.testing.assert_array_equal(cells, data)  # nothing changed since the last frame
        self.assertEqual(reply.occupied_cells, int((cells == 100).sum()))
        self.assertEqual(reply.free_cells, int((cells == 0).sum()))
        self.assertGreater(reply.occupied_cells, 200)  # walls and boxes (1146 offline)
        self.assertGreater(reply.free_cells, 1000)     # the room's floor (5323 offline)
        octomap = os.path.join(os.path.dirname(path), "map.bt")
        reply = rospy.ServiceProxy("/dslam/save_octomap", SaveMap)(octomap)
        self.assertTrue(reply.success, reply.message)
        self.assertGreater(reply.points, 1000)  # occupied leaves
        with open(octomap, "rb") as handle:
            self.assertEqual(handle.readline(), b"# Octomap OcTree binary file\n")
        origin, s = numbers(keys["origin"]), float(keys["resolution"])
        camera = (int(np.floor(-origin[0] / s)), int(np.floor(-origin[1] / s)))
        self.assertEqual(cells[camera[1], camera[0]], 0, "the first camera's cell is not free")

        walked = [c for c in path_cells(folder, keys)
                  if 0 <= c[0] < cells.shape[1] and 0 <= c[1] < cells.shape[0]]
        values = [cells[j, i] for i, j in walked]
        occupied = sum(v == 100 for v in values) / len(values)
        free = sum(v == 0 for v in values) / len(values)
        rospy.loginfo("grid_check: %d path cells, %.3f occupied, %.3f free", len(values),
                      occupied, free)
        self.assertGreater(len(values), 30)
        self.assertLessEqual(occupied, PATH_OCCUPIED_MAX)
        self.assertGreaterEqual(free, PATH_FREE_MIN)


if __name__ == "__main__":
    rostest.rosrun("dslam", "grid", GridTest)
