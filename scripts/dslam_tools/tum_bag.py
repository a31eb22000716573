"""Converting a TUM RGB-D layout folder into a rosbag with the official TUM topics.

Topics (TUM bag layout): /camera/rgb/image_color (sensor_msgs/Image rgb8),
/camera/depth/image (32FC1, metres, NaN where the PNG holds 0), /camera/rgb/camera_info
(from camera.yaml, once per colour frame with the colour stamp) and optionally
/camera/mask/image (mono16 object ids). Header stamps and bag record times are the file stamps.
Images are read and written one at a time, so memory stays bounded whatever the sequence length.
"""

import os
import time

import cv2
import genpy
import numpy as np
import rosbag
from sensor_msgs.msg import CameraInfo, Image

from dslam_tools import dataset
from dslam_tools.progress import ProgressBar

RGB_TOPIC = "/camera/rgb/image_color"
DEPTH_TOPIC = "/camera/depth/image"
INFO_TOPIC = "/camera/rgb/camera_info"
MASK_TOPIC = "/camera/mask/image"
DEFAULT_FRAME_ID = "openni_rgb_optical_frame"
COMPRESSION = {"none": rosbag.Compression.NONE, "lz4": rosbag.Compression.LZ4,
               "bz2": rosbag.Compression.BZ2}


def ros_time(entry):
    """genpy.Time of a dataset.StampedFile, exact to the nanosecond from the stamp text."""
    secs, nsecs = dataset.stamp_to_sec_nsec(entry.stamp_text)
    return genpy.Time(secs, nsecs)


def make_image(pixels, encoding, stamp, frame_id, seq):
    """sensor_msgs/Image from a contiguous little-endian array [H,W] or [H,W,C]."""
    message = Image()
    message.header.seq = seq
    message.header.stamp = stamp
    message.header.frame_id = frame_id
    message.height, message.width = pixels.shape[:2]
    message.encoding = encoding
    message.is_bigendian = 0
    message.step = pixels.strides[0]
    message.data = pixels.tobytes()
    return message


def make_camera_info(camera, stamp, frame_id, seq):
    """sensor_msgs/CameraInfo from a load_camera_yaml() dict: K, D plumb_bob [k1 k2 p1 p2 k3],
    R identity, P = [K | 0]."""
    fx, fy, cx, cy = camera["fx"], camera["fy"], camera["cx"], camera["cy"]
    message = CameraInfo()
    message.header.seq = seq
    message.header.stamp = stamp
    message.header.frame_id = frame_id
    message.width, message.height = camera["width"], camera["height"]
    message.distortion_model = "plumb_bob"
    message.D = list(camera["distortion"])
    message.K = [fx, 0.0, cx, 0.0, fy, cy, 0.0, 0.0, 1.0]
    message.R = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
    message.P = [fx, 0.0, cx, 0.0, 0.0, fy, cy, 0.0, 0.0, 0.0, 1.0, 0.0]
    return message


def read_png(path, want_uint16):
    """Reads a PNG unchanged; raises IOError when missing/unreadable or of the wrong bit depth."""
    pixels = cv2.imread(path, cv2.IMREAD_UNCHANGED)
    if pixels is None:
        raise IOError("cannot read image %s" % path)
    if want_uint16 and (pixels.dtype != np.uint16 or pixels.ndim != 2):
        raise IOError("%s: expected a single-channel 16-bit PNG, got %s %s" %
                      (path, pixels.dtype, pixels.shape))
    return pixels


def colour_to_rgb8(pixels, path):
    """BGR / BGRA / grey 8-bit image from OpenCV -> contiguous RGB [H,W,3] uint8."""
    if pixels.dtype != np.uint8:
        raise IOError("%s: expected an 8-bit colour PNG, got %s" % (path, pixels.dtype))
    if pixels.ndim == 2:
        return cv2.cvtColor(pixels, cv2.COLOR_GRAY2RGB)
    code = cv2.COLOR_BGRA2RGB if pixels.shape[2] == 4 else cv2.COLOR_BGR2RGB
    return cv2.cvtColor(pixels, code)


def depth_to_metres(raw, depth_scale):
    """16-bit depth PNG [H,W] -> little-endian float32 metres, 0 (no measurement) -> NaN.
    The arithmetic is the offline reader's (DepthFromScaledUint16: cv::Mat::convertTo with scale
    1 / depth_scale, a float multiply), so that the node given the bag sees the very depths
    dslam_run_dataset reads from the PNG files (a float division differs in the last bit for
    about 30 % of the values)."""
    metres = raw.astype("<f4")
    metres *= np.float32(1.0 / depth_scale)
    metres[raw == 0] = np.nan
    return metres


def list_events(folder, with_mask):
    """All images of the folder as (stamp_s, kind order, kind, StampedFile), sorted by time.
    Kinds: 'rgb', 'depth', 'mask'. Raises IOError when a required list is missing."""
    lists = [("rgb", "rgb.txt"), ("depth", "depth.txt")]
    if with_mask:
        lists.append(("mask", "mask.txt"))
    events = []
    for order, (kind, name) in enumerate(lists):
        path = os.path.join(folder, name)
        if not os.path.isfile(path):
            raise IOError("missing %s" % path)
        events.extend((entry.stamp_s, order, kind, entry) for entry in dataset.read_file_list(path))
    events.sort(key=lambda event: event[:2])
    return events


class _Writer(object):
    """Turns each image event into bag messages; counts messages per topic."""

    def __init__(self, bag, folder, camera, frame_id):
        self._bag = bag
        self._folder = folder
        self._camera = camera
        self._frame_id = frame_id
        self.counts = {RGB_TOPIC: 0, DEPTH_TOPIC: 0, INFO_TOPIC: 0, MASK_TOPIC: 0}

    def write(self, kind, entry):
        """Reads the image of one list entry and writes its message(s)."""
        path = os.path.join(self._folder, entry.path)
        stamp = ros_time(entry)
        if kind == "rgb":
            pixels = colour_to_rgb8(read_png(path, False), path)
            self._check_size(pixels, path)
            self._put(RGB_TOPIC, make_image(pixels, "rgb8", stamp, self._frame_id,
                                            self.counts[RGB_TOPIC]), stamp)
            self._put(INFO_TOPIC, make_camera_info(self._camera, stamp, self._frame_id,
                                                   self.counts[INFO_TOPIC]), stamp)
        elif kind == "depth":
            raw = read_png(path, True)
            self._check_size(raw, path)
            metres = depth_to_metres(raw, self._camera["depth_scale"])
            self._put(DEPTH_TOPIC, make_image(metres, "32FC1", stamp, self._frame_id,
                                              self.counts[DEPTH_TOPIC]), stamp)
        else:
            raw = read_png(path, True).astype("<u2", copy=False)
            self._check_size(raw, path)
            self._put(MASK_TOPIC, make_image(raw, "mono16", stamp, self._frame_id,
                                             self.counts[MASK_TOPIC]), stamp)

    def _put(self, topic, message, stamp):
        self._bag.write(topic, message, t=stamp)
        self.counts[topic] += 1

    def _check_size(self, pixels, path):
        expected = (self._camera["height"], self._camera["width"])
        if pixels.shape[:2] != expected:
            raise ValueError("%s is %dx%d but camera.yaml says %dx%d" %
                             (path, pixels.shape[1], pixels.shape[0], expected[1], expected[0]))


def convert(folder, output, camera_path="", compression="lz4", with_mask=False,
            frame_id=DEFAULT_FRAME_ID, progress=True):
    """Converts the TUM folder into the bag `output` (deleted again on failure). Returns a dict:
    counts (messages per topic), seconds (wall time), bytes (bag file size)."""
    start = time.time()
    camera = dataset.load_camera_yaml(dataset.resolve_camera_yaml(folder, camera_path))
    events = list_events(folder, with_mask)
    bar = ProgressBar(len(events)) if progress else None
    bag = rosbag.Bag(output, "w", compression=COMPRESSION[compression])
    try:
        writer = _Writer(bag, folder, camera, frame_id)
        for done, (_, _, kind, entry) in enumerate(events, 1):
            writer.write(kind, entry)
            if bar:
                bar.update(done)
        bag.close()
    except BaseException:
        bag.close()
        os.remove(output)
        raise
    return {"counts": writer.counts, "seconds": time.time() - start,
            "bytes": os.path.getsize(output)}
