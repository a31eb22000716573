"""Hand-made input sets for the dslam nodelet, one at a time: a rendered sequence as ready
messages and a node handle that publishes a set and waits for its status message; nodes started
from dslam.launch with arguments and parameters of a test's own (the rostests robustness_check.py,
keyframe_map_start_check.py and frames_check.py)."""
import os
import signal
import subprocess
import sys
import time

import cv2
import genpy
import rospkg
import rospy
from nav_msgs.msg import Odometry, Path
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import CameraInfo, Image
from tf2_msgs.msg import TFMessage

from dslam.msg import FrameStatus

sys.path.insert(0, os.path.join(rospkg.RosPack().get_path("dslam"), "scripts"))
from dslam_tools import dataset, tum_bag  # noqa: E402
from rostest_helpers import CAMERA_TOPICS, Recorder  # noqa: E402 (beside this file)


class Sequence:
    """The rendered frames as ready messages (colour rgb8, depth 32FC1 metres, camera_info)."""

    def __init__(self, folder):
        camera = dataset.load_camera_yaml(os.path.join(folder, "camera.yaml"))
        rgb = dataset.read_file_list(os.path.join(folder, "rgb.txt"))
        depth = dataset.read_file_list(os.path.join(folder, "depth.txt"))
        self.camera = camera
        self.colour = [tum_bag.colour_to_rgb8(cv2.imread(os.path.join(folder, e.path)), e.path)
                       for e in rgb]
        self.depth = [tum_bag.depth_to_metres(
            tum_bag.read_png(os.path.join(folder, e.path), True), camera["depth_scale"])
            for e in depth]

    def messages(self, i, stamp_s, colour_frame="cam", depth_frame="cam", encoding="rgb8"):
        stamp = genpy.Time.from_sec(stamp_s) if stamp_s else genpy.Time()
        colour = tum_bag.make_image(self.colour[i], "rgb8", stamp, colour_frame, i)
        colour.encoding = encoding
        depth = tum_bag.make_image(self.depth[i], "32FC1", stamp, depth_frame, i)
        info = tum_bag.make_camera_info(self.camera, stamp, colour_frame, i)
        return colour, depth, info


class Node:
    """Publishers into the nodelet and a recorder of its outputs."""

    def __init__(self, ns="/dslam"):
        self.rec = Recorder()
        self.pubs = [rospy.Publisher(topic, kind, queue_size=5)
                     for topic, kind in zip(CAMERA_TOPICS, (Image, Image, CameraInfo))]
        self.subs = [self.rec.subscribe(ns + "/status", FrameStatus, "status"),
                     self.rec.subscribe("/rosout", Log, "log", queue_size=1000),
                     self.rec.subscribe(ns + "/path", Path, "path"),
                     self.rec.subscribe(ns + "/odom", Odometry, "odom"),
                     self.rec.subscribe("/tf", TFMessage, "tf", queue_size=1000)]

    def path_lengths(self):
        """The number of poses of each path message so far."""
        return [len(msg.poses) for msg in self.rec.messages("path")]

    def wait_connected(self):
        """Waits until the node subscribes to the camera topics and `status` (which send() waits
        for) has its publisher, up to 30 s in all: rospy connects in the background, and a status
        published before its subscriber connected is never received. (Other recorded topics may
        have no publisher in a test's setting, e.g. /tf with publish_tf false.)"""
        deadline = time.time() + 30.0
        while time.time() < deadline and (any(p.get_num_connections() == 0 for p in self.pubs) or
                                          self.subs[0].get_num_connections() == 0):
            time.sleep(0.1)
        if self.subs[0].get_num_connections() == 0:
            raise AssertionError("no publisher of %s within 30 s" % self.subs[0].name)

    def send(self, messages, expect_status=True):
        """Publishes one set; returns its status message (waits up to 20 s)."""
        count = self.rec.count("status")
        for pub, msg in zip(self.pubs, messages):
            if msg is not None:
                pub.publish(msg)
        if not expect_status:
            return None
        deadline = time.time() + 20.0
        while time.time() < deadline:
            statuses = self.rec.messages("status")
            if len(statuses) > count:
                return statuses[count]
            time.sleep(0.01)
        raise AssertionError("no status for the set stamped %s" % messages[0].header.stamp)

    def logged(self, text):
        return any(text in log.msg for log in self.rec.messages("log"))

    def wait_logged(self, text, timeout_s=5.0):
        deadline = time.time() + timeout_s
        while time.time() < deadline and not self.logged(text):
            time.sleep(0.05)
        return self.logged(text)


def launch_node(work, ns, args=None, params=None):
    """Starts dslam.launch in namespace `ns` with exact sync, the launch arguments `args` and the
    node parameters `params` (name -> value; set after the launch file's own), through a launch
    file written into the folder `work`; returns the roslaunch process."""
    path = os.path.join(work, ns + ".launch")
    arg_lines = ['    <arg name="%s" value="%s"/>' % item for item in (args or {}).items()]
    param_lines = ['  <param name="/%s/odometry/%s" value="%s"/>' % (ns, key, value)
                   for key, value in (params or {}).items()]
    with open(path, "w") as out:
        out.write("""<launch>
  <include file="$(find dslam)/launch/dslam.launch">
    <arg name="ns" value="%s"/> <arg name="manager" value="%s_manager"/>
    <arg name="exact_sync" value="true"/>
%s
  </include>
%s
</launch>
""" % (ns, ns, "\n".join(arg_lines), "\n".join(param_lines)))
    return subprocess.Popen(["roslaunch", path])


def start_node(work, ns, args=None, params=None, topics=()):
    """launch_node, and a Node on it that also records `topics` ((topic, class, name), ...);
    returns (process, node) once the node's services are up and its inputs connected."""
    process = launch_node(work, ns, args, params)
    node = Node("/" + ns)
    for topic, kind, name in topics:
        node.rec.subscribe(topic, kind, name, queue_size=100)
    rospy.wait_for_service("/%s/save_trajectory" % ns, timeout=30.0)
    node.wait_connected()
    return process, node


def stop(process):
    """Stops a roslaunch process as Ctrl-C would and waits for it."""
    process.send_signal(signal.SIGINT)
    process.wait(timeout=60)
