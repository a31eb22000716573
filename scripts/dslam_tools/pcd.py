"""Reads the PCD files dslam writes (dslam_run_dataset --map, the save_map service): fields x y z
rgb (rgb packed 0x00RRGGBB in 4 bytes), DATA ascii or binary."""

import numpy as np


def read_pcd(path):
    """Returns (points Nx3 float64 [m], colours Nx3 float in [0, 1], RGB)."""
    with open(path, "rb") as handle:
        header = {}
        while True:
            line = handle.readline().decode("ascii").strip()
            if not line or line.startswith("#"):
                continue
            key, _, value = line.partition(" ")
            header[key] = value.split()
            if key == "DATA":
                break
        body = handle.read()
    fields, sizes, types = header["FIELDS"], header["SIZE"], header["TYPE"]
    count = int(header["POINTS"][0])
    if fields[:4] != ["x", "y", "z", "rgb"]:
        raise ValueError(f"{path}: fields {fields}, expected x y z rgb")
    if header["DATA"][0] == "ascii":
        rows = np.array([row.split() for row in body.decode("ascii").splitlines() if row.strip()],
                        dtype=np.float64)
        xyz, rgb = rows[:, :3], rows[:, 3].astype(np.float32).view(np.uint32)
    elif header["DATA"][0] == "binary":
        kinds = {"F": "f", "U": "u", "I": "i"}
        dtype = np.dtype([(name, "<" + kinds[t] + s) for name, t, s in zip(fields, types, sizes)])
        data = np.frombuffer(body[: dtype.itemsize * count], dtype=dtype)
        xyz = np.stack([data["x"], data["y"], data["z"]], axis=1).astype(np.float64)
        rgb = data["rgb"].view(np.uint32) if data["rgb"].dtype != np.uint32 else data["rgb"]
    else:
        raise ValueError(f"{path}: DATA {header['DATA'][0]} not supported")
    colours = np.stack([(rgb >> 16) & 255, (rgb >> 8) & 255, rgb & 255], axis=1) / 255.0
    return xyz, colours
