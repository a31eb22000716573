"""Reads the occupancy grid files dslam writes (dslam_run_dataset --grid, the save_grid service:
map_server's YAML with dslam's keys T_world_grid, min_height_m, max_height_m, floor_from_plane,
and the 8-bit binary PGM beside it; include/dslam/mapping/occupancy_grid.h)."""

import os

import numpy as np


def read_keys(yaml_path):
    """The YAML's top-level keys as strings (its lines `key: value`; comments skipped)."""
    keys = {}
    with open(yaml_path) as handle:
        for line in handle:
            if line.strip() and not line.startswith("#"):
                key, value = line.split(":", 1)
                keys[key.strip()] = value.strip()
    return keys


def numbers(text):
    """The numbers of a YAML list `[a, b, ...]`."""
    return [float(v) for v in text.strip("[]").split(",")]


def read_pgm(path):
    """The pixels of an 8-bit binary PGM with one comment line, as written (uint8, the first row
    is the grid's highest y): 0 occupied, 254 free, 205 unknown."""
    with open(path, "rb") as handle:
        fields = handle.read().split(b"\n", 3)  # P5, the comment, the size, "255\n" + pixels
    if fields[0] != b"P5":
        raise ValueError(f"{path}: not a binary PGM")
    width, height = (int(v) for v in fields[2].split())
    pixels = fields[3][len(b"255\n"):]
    if len(pixels) != width * height:
        raise ValueError(f"{path}: {len(pixels)} pixels, not {width} x {height}")
    return np.frombuffer(pixels, dtype=np.uint8).reshape(height, width)


def read_grid(yaml_path):
    """(keys, pixels): read_keys of the YAML and read_pgm of its image."""
    keys = read_keys(yaml_path)
    return keys, read_pgm(os.path.join(os.path.dirname(yaml_path), keys["image"]))


def cells(pixels):
    """The pixels as nav_msgs/OccupancyGrid's data: row j from the lowest y, 100 occupied,
    0 free, -1 unknown."""
    out = np.full(pixels.shape, -1, dtype=np.int8)
    out[pixels == 0] = 100
    out[pixels == 254] = 0
    return out[::-1]


def world_grid_matrix(keys):
    """4x4 T_world_grid of the YAML's [x, y, z, qx, qy, qz, qw]."""
    x, y, z, qx, qy, qz, qw = numbers(keys["T_world_grid"])
    T = np.eye(4)
    T[:3, :3] = [[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
                 [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
                 [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]]
    T[:3, 3] = [x, y, z]
    return T
