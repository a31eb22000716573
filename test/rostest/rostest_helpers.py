"""What the rostests share beside the scenes (test_scenes.py): a recorder of the messages a test
subscribes to, playing a scene's bag into the dslam node, and reading poses and the map -> odom
transforms of /tf."""
import collections
import subprocess
import threading
import time
import types

import numpy as np
import rospy

CAMERA_TOPICS = ["/camera/rgb/image_color", "/camera/depth/image", "/camera/rgb/camera_info"]


class Recorder:
    """Every message of the topics subscribed through it, by name, in arrival order, each with
    its arrival time (time.monotonic(), s); safe to read while callbacks record."""

    def __init__(self):
        self._lock = threading.Lock()
        self._received = collections.defaultdict(list)  # name -> [(arrival_s, msg)]
        self._subscribers = []

    def subscribe(self, topic, msg_class, name, queue_size=100):
        """A rospy.Subscriber of `topic` that records its messages as `name`."""
        subscriber = rospy.Subscriber(topic, msg_class, self.callback(name), queue_size=queue_size)
        self._subscribers.append(subscriber)
        return subscriber

    def wait_until_connected(self, timeout_s=30.0):
        """Waits until every subscriber made by subscribe() is connected to a publisher: rospy
        connects in the background, and a message published before that is never received.
        Raises AssertionError naming the topics still unconnected after `timeout_s`."""
        deadline = time.monotonic() + timeout_s
        while True:
            waiting = [s.name for s in self._subscribers if s.get_num_connections() == 0]
            if not waiting:
                return
            if time.monotonic() > deadline:
                raise AssertionError("no publisher connected within %.0f s: %s"
                                     % (timeout_s, ", ".join(waiting)))
            time.sleep(0.05)

    def wait_for(self, done, timeout_s=30.0):
        """Waits until `done(self)` is true or `timeout_s` passed (the caller asserts what it
        needs afterwards): for a node still working through frames when the player stopped."""
        deadline = time.monotonic() + timeout_s
        while not done(self) and time.monotonic() < deadline:
            time.sleep(0.05)

    def callback(self, name):
        """A subscriber callback that records each message as `name`."""
        def store(msg):
            with self._lock:
                self._received[name].append((time.monotonic(), msg))
        return store

    def timed(self, name):
        """[(arrival_s, msg)] of `name` so far (a copy)."""
        with self._lock:
            return list(self._received.get(name, []))

    def messages(self, name):
        """The messages of `name` so far (a copy)."""
        return [msg for _, msg in self.timed(name)]

    def count(self, name):
        with self._lock:
            return len(self._received.get(name, []))

    def last(self, name):
        """The newest message of `name` (IndexError when none arrived)."""
        with self._lock:
            return self._received.get(name, [])[-1][1]


def play_bag(bag, rate=0.5, settle_s=2.0, node="/dslam", options=(), recorder=None):
    """Plays the camera topics of `bag` (test_scenes.scene(..., with_bag=True)) into the dslam
    node in namespace `node`: waits for it (its save_trajectory service, up to 30 s) and for
    `recorder`'s subscribers to connect (Recorder.wait_until_connected, when given), plays at
    `rate` times real time once a node subscribes (with rosbag play's `options`, e.g. ["-s", "1",
    "-u", "2"]: from 1 s into the bag for 2 s), then waits `settle_s` for it to process the last
    frames."""
    rospy.wait_for_service(node + "/save_trajectory", timeout=30.0)
    if recorder is not None:
        recorder.wait_until_connected()
    subprocess.check_call(["rosbag", "play", "--quiet", "-r", str(rate), "--wait-for-subscribers"]
                          + list(options) + [bag, "--topics"] + CAMERA_TOPICS)
    rospy.sleep(settle_s)


def matrix(translation, rotation):
    """4x4 homogeneous matrix of a geometry_msgs translation (or position) and quaternion."""
    x, y, z, w = rotation.x, rotation.y, rotation.z, rotation.w
    out = np.identity(4)
    out[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                   [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                   [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    out[:3, 3] = [translation.x, translation.y, translation.z]
    return out


def map_odom_transforms(rec, name="tf", map_frame="map", odom_frame="odom"):
    """{stamp (ns): TransformStamped} of the map -> odom transforms recorded as `name` (/tf)."""
    return {t.header.stamp.to_nsec(): t for msg in rec.messages(name) for t in msg.transforms
            if t.header.frame_id == map_frame and t.child_frame_id == odom_frame}


def tum_matrix(row):
    """4x4 pose of a TUM trajectory row (stamp tx ty tz qx qy qz qw)."""
    return matrix(types.SimpleNamespace(x=row[1], y=row[2], z=row[3]),
                  types.SimpleNamespace(x=row[4], y=row[5], z=row[6], w=row[7]))


def is_identity(transform):
    """Whether a geometry_msgs/Transform is exactly the identity."""
    t, q = transform.translation, transform.rotation
    return (t.x, t.y, t.z, q.x, q.y, q.z, abs(q.w)) == (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
