"""Reading TUM RGB-D layout folders: file lists (rgb.txt, depth.txt, mask.txt) and camera.yaml."""

import os

import yaml

CAMERA_KEYS = ("width", "height", "fx", "fy", "cx", "cy")
DISTORTION_KEYS = ("k1", "k2", "p1", "p2", "k3")


class StampedFile(object):
    """One line of a TUM file list: the stamp as written (text), as seconds, and the file path."""

    __slots__ = ("stamp_text", "stamp_s", "path")

    def __init__(self, stamp_text, path):
        self.stamp_text = stamp_text  # exact decimal text, e.g. "1548339829.93029"
        self.stamp_s = float(stamp_text)  # [s]
        self.path = path  # relative to the dataset folder

    def __repr__(self):
        return "StampedFile(%s, %s)" % (self.stamp_text, self.path)


def stamp_to_sec_nsec(stamp_text):
    """Splits a decimal stamp text ("1548339829.93029") into integer (secs, nsecs) exactly,
    without a round trip through a float (which loses the last digits of 10-digit stamps)."""
    text = stamp_text.strip()
    if text.startswith("-"):
        raise ValueError("negative stamp %r" % stamp_text)
    whole, _, fraction = text.partition(".")
    if not whole.isdigit() or (fraction and not fraction.isdigit()):
        raise ValueError("malformed stamp %r" % stamp_text)
    nsecs = int((fraction + "000000000")[:9]) if fraction else 0
    if len(fraction) > 9 and int(fraction[9]) >= 5:  # round to the nearest nanosecond
        nsecs += 1
    secs = int(whole)
    if nsecs >= 1000000000:
        secs, nsecs = secs + 1, nsecs - 1000000000
    return secs, nsecs


def read_file_list(path):
    """Reads a TUM file list ("timestamp filename" lines, '#' comments), sorted by stamp.
    Raises ValueError naming the file and line on a malformed line."""
    entries = []
    with open(path) as handle:
        for number, line in enumerate(handle, 1):
            fields = line.split()
            if not fields or fields[0].startswith("#"):
                continue
            if len(fields) < 2:
                raise ValueError("%s:%d: expected 'timestamp filename'" % (path, number))
            try:
                entries.append(StampedFile(fields[0], fields[1]))
            except ValueError:
                raise ValueError("%s:%d: bad timestamp %r" % (path, number, fields[0]))
    entries.sort(key=lambda entry: entry.stamp_s)
    return entries


def load_camera_yaml(path):
    """Reads the package's camera.yaml into a dict with float intrinsics (fx fy cx cy [px]),
    int width/height [px], distortion list [k1 k2 p1 p2 k3] (missing keys 0), depth_scale
    (PNG units per metre, default 5000) and groundtruth_correction ('none' or 'bonn')."""
    with open(path) as handle:
        root = yaml.safe_load(handle) or {}
    missing = [key for key in CAMERA_KEYS if key not in root]
    if missing:
        raise ValueError("%s: missing key(s) %s" % (path, ", ".join(missing)))
    camera = {key: float(root[key]) for key in CAMERA_KEYS}
    camera["width"] = int(root["width"])
    camera["height"] = int(root["height"])
    camera["distortion"] = [float(root.get(key, 0.0)) for key in DISTORTION_KEYS]
    camera["depth_scale"] = float(root.get("depth_scale", 5000.0))
    if not camera["depth_scale"] > 0:
        raise ValueError("%s: depth_scale must be > 0" % path)
    correction = str(root.get("groundtruth_correction", "none"))
    if correction not in ("none", "bonn"):
        raise ValueError("%s: groundtruth_correction must be none or bonn, got %r" %
                         (path, correction))
    camera["groundtruth_correction"] = correction
    return camera


def resolve_camera_yaml(folder, camera_path):
    """Returns camera_path, or FOLDER/camera.yaml when camera_path is empty."""
    path = camera_path or os.path.join(folder, "camera.yaml")
    if not os.path.isfile(path):
        raise IOError("camera file not found: %s (pass --camera)" % path)
    return path
