#!/usr/bin/env python3
"""Relocalisation benchmark: frames dropped from the input (a USB hiccup, a bag recorded with
gaps) while the stamps go on, so the motion model's prediction misses the jump, and frames
blanked (a covered lens: black colour, no depth) for longer than tracking.lost_frames_before_reset.
For every scenario and seed it renders the sequence once into --cache, writes a copy whose
rgb.txt and depth.txt leave out the --drop ranges and point the --blank ranges at a black image
and an empty depth image (other images linked, not copied), runs
  dslam_run_dataset --dataset D --trajectory T --status S --config C
with `tracking.relocalisation` true and false, evaluates both with dslam_eval against the full
ground truth, and prints a Markdown table: frames lost, re-initialisations (state
`initialised` after the first frame), frames `recovered`, ATE and rotational RPE of each.
The shared Bonn segment is included when ../shared/data holds it. Usage:
  scripts/relocalisation_benchmark.py [--scenarios fast_rotation,static_room] [--seeds 1 2 3]
                                      [--drop 100:12] [--blank 200:20] [--frames 300]
                                      [--cache build/relocalisation_bench]
"""
import argparse
import csv
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark import BIN, REPO, SHARED, render, run  # noqa: E402

VARIANTS = {"off": "false", "on": "true"}  # tracking.relocalisation


def parse_drops(text):
    """'100:12,200:12' -> [(100, 12), (200, 12)]: (first dropped frame index, frames dropped)."""
    return [tuple(int(x) for x in part.split(":")) for part in text.split(",") if part]


def blank_images(folder, out):
    """Writes out/blank_rgb.png (black) and out/blank_depth.png (16-bit zeros: no depth) of the
    size of the sequence's first colour image; returns their names relative to `out`."""
    import cv2  # noqa: E402  (python3-opencv; only needed for --blank)
    import numpy as np  # noqa: E402
    with open(os.path.join(folder, "rgb.txt")) as f:
        first = next(line.split()[1] for line in f if line.strip() and not line.startswith("#"))
    height, width = cv2.imread(os.path.join(folder, first)).shape[:2]
    cv2.imwrite(os.path.join(out, "blank_rgb.png"), np.zeros((height, width, 3), np.uint8))
    cv2.imwrite(os.path.join(out, "blank_depth.png"), np.zeros((height, width), np.uint16))
    return {"rgb.txt": "blank_rgb.png", "depth.txt": "blank_depth.png"}


def dropped_copy(folder, drops, out, blanks=()):
    """`out`: `folder` with the frames of `drops` left out of rgb.txt and depth.txt and those of
    `blanks` (same form) pointing at blank images; the rest linked."""
    skip = {first + k for first, count in drops for k in range(count)}
    blank = {first + k for first, count in blanks for k in range(count)}
    os.makedirs(out, exist_ok=True)
    blank_files = blank_images(folder, out) if blank else {}
    for name in os.listdir(folder):
        source, target = os.path.join(folder, name), os.path.join(out, name)
        if name in ("rgb.txt", "depth.txt"):
            with open(source) as f:
                lines = f.readlines()
            frames = [line for line in lines if line.strip() and not line.startswith("#")]
            with open(target, "w") as f:
                f.writelines(line for line in lines if line.startswith("#"))
                for i, line in enumerate(frames):
                    if i in blank:
                        line = f"{line.split()[0]} {blank_files[name]}\n"
                    if i not in skip:
                        f.write(line)
        elif not os.path.lexists(target):
            os.symlink(os.path.abspath(source), target)
    return out


def run_variant(folder, camera, variant, out_dir):
    """Runs one variant; returns (lost, re-initialisations, recovered, ATE, RPE deg/s)."""
    config = os.path.join(out_dir, f"relocalisation_{variant}.yaml")
    with open(config, "w") as f:
        f.write(f"tracking:\n  relocalisation: {VARIANTS[variant]}\n")
    traj = os.path.join(out_dir, f"trajectory_{variant}.txt")
    status = os.path.join(out_dir, f"status_{variant}.csv")
    cmd = [os.path.join(BIN, "dslam_run_dataset"), "--dataset", folder, "--trajectory", traj,
           "--status", status, "--config", config, "--quiet"]
    run(cmd + (["--camera", camera] if camera else []))
    metrics = os.path.join(out_dir, f"eval_{variant}.json")
    run([os.path.join(BIN, "dslam_eval"), "--groundtruth", os.path.join(folder, "groundtruth.txt"),
         "--trajectory", traj, "--camera", camera or os.path.join(folder, "camera.yaml"),
         "--json", metrics])
    with open(status) as f:
        states = [row["state"] for row in csv.DictReader(f)]
    with open(metrics) as f:
        ev = json.load(f)
    return (states.count("lost"), states[1:].count("initialised"), states.count("recovered"),
            ev["ate_rmse_m"], ev["rpe_rot_rmse_deg_per_s"])


def row(name, results):
    off, on = results["off"], results["on"]
    return (f"| {name} | {off[0]} / {on[0]} | {off[1]} / {on[1]} | {on[2]} | "
            f"{off[3]:.4f} / {on[3]:.4f} | {off[4]:.2f} / {on[4]:.2f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenarios", default="fast_rotation,static_room,walking_halfsphere")
    parser.add_argument("--seeds", nargs="+", type=int, default=[1, 2, 3])
    parser.add_argument("--drop", default="100:12", help="FIRST:COUNT,...: frames left out")
    parser.add_argument("--blank", default="200:20", help="FIRST:COUNT,...: frames blanked")
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--cache", default=os.path.join(REPO, "build", "relocalisation_bench"))
    args = parser.parse_args()
    drops, blanks = parse_drops(args.drop), parse_drops(args.blank)
    tag = "drop" + "_".join(f"{a}-{b}" for a, b in drops) + \
        "_blank" + "_".join(f"{a}-{b}" for a, b in blanks)
    sequences = []
    for scenario in filter(None, args.scenarios.split(",")):
        for seed in args.seeds:
            folder = render(scenario, seed, args.frames, os.path.join(args.cache, "sequences"))
            sequences.append((f"{scenario} s{seed}", folder, ""))
    bonn = os.path.join(SHARED, "bonn_crowd_frames300-599")
    if os.path.isdir(bonn):
        sequences.append(("Bonn crowd 300-599", bonn, os.path.join(bonn, "camera.yaml")))
    print(f"frames (first:count) dropped: {args.drop or 'none'}, blanked: {args.blank or 'none'}; "
          "'off / on' = tracking.relocalisation\n")
    print("| sequence | lost off / on | re-initialisations off / on | recovered on | "
          "ATE [m] off / on | RPE [deg/s] off / on |\n|---|---|---|---|---|---|")
    for name, folder, camera in sequences:
        base = os.path.basename(os.path.normpath(folder))
        copy = dropped_copy(folder, drops, os.path.join(args.cache, "dropped", f"{base}_{tag}"),
                            blanks)
        out_dir = os.path.join(args.cache, "runs", f"{base}_{tag}")
        os.makedirs(out_dir, exist_ok=True)
        results = {v: run_variant(copy, camera, v, out_dir) for v in VARIANTS}
        print(row(name, results), flush=True)


if __name__ == "__main__":
    main()
