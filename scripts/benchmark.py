#!/usr/bin/env python3
"""Front-end benchmark: accuracy, segmentation and speed with static point determination on and
off (the static-world baseline) in the same run. Prints Markdown tables for BENCHMARKS.md.

Synthetic scenarios are rendered once per seed into --cache (seeds 1, 2, 3 averaged); real data
from ../shared/data is used when present. Usage:
  scripts/benchmark.py [--scenarios walking,static_room] [--seeds 1,2,3] [--frames 300]
                       [--real] [--cache build/bench] [--config params.yaml]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WS = os.environ.get("DSLAM_WS", os.path.join(REPO, "build", "ws"))
BIN = os.path.join(WS, "devel", "lib", "dslam")
SHARED = os.path.join(os.path.dirname(REPO), "shared", "data")
SCENARIOS = ["walking", "walking_static", "close_person", "walking_halfsphere", "slow_box",
             "nonrigid_sheet", "static_room"]


def run(cmd):
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if proc.returncode != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{proc.stdout}\n{proc.stderr}")
    return proc.stdout


def render(scenario, seed, frames, cache):
    folder = os.path.join(cache, f"{scenario}_f{frames}_s{seed}")
    if not os.path.exists(os.path.join(folder, "groundtruth.txt")):
        run([os.path.join(BIN, "dslam_synth"), "--scenario", scenario, "--frames", str(frames),
             "--seed", str(seed), "--output", folder])
    return folder


def evaluate(folder, camera, static_points, out_dir, config):
    tag = "on" if static_points else "off"
    traj = os.path.join(out_dir, f"trajectory_{tag}.txt")
    summary = os.path.join(out_dir, f"summary_{tag}.json")
    cmd = [os.path.join(BIN, "dslam_run_dataset"), "--dataset", folder, "--trajectory", traj,
           "--status", os.path.join(out_dir, f"status_{tag}.csv"), "--summary", summary,
           "--static-points", tag, "--quiet"]
    if camera:
        cmd += ["--camera", camera]
    if config:
        cmd += ["--config", config]
    run(cmd)
    metrics = os.path.join(out_dir, f"eval_{tag}.json")
    ev = [os.path.join(BIN, "dslam_eval"), "--groundtruth", os.path.join(folder, "groundtruth.txt"),
          "--trajectory", traj, "--frames", os.path.join(folder, "rgb.txt"), "--json", metrics]
    ev += ["--camera", camera or os.path.join(folder, "camera.yaml")]
    run(ev)
    with open(summary) as f:
        result = json.load(f)
    with open(metrics) as f:
        result.update(json.load(f))
    return result


def fmt(value, digits=4):
    return "n/a" if value is None else f"{value:.{digits}f}"


def row(name, on, off):
    ratio = off["ate_rmse_m"] / max(on["ate_rmse_m"], 1e-9)
    seg = (f"{on['dynamic_precision']:.3f} | {on['dynamic_recall']:.3f} | "
           f"{on['false_dynamic_rate']:.4f}") if "dynamic_recall" in on else "- | - | -"
    seg += f" | {on['labelled_dynamic_share']:.4f}"
    tracked = on["frames_with_pose"] / max(on["frames"], 1)
    return (f"| {name} | {on['ate_rmse_m']:.4f} | {off['ate_rmse_m']:.4f} | {ratio:.1f}x | "
            f"{fmt(on.get('rpe_trans_rmse_m_per_s'))} | {tracked:.3f} | {fmt(on['coverage'], 3)} | {seg} | "
            f"{on['median_total_ms']:.1f} | {on['median_static_points_ms']:.2f} "
            f"({on['median_graph_points']:.0f} pts) |")


def mean_of(results):
    keys = [k for k, v in results[0].items() if isinstance(v, (int, float)) and not isinstance(v, bool)]
    return {k: statistics.mean(r[k] for r in results if r.get(k) is not None)
            for k in keys if all(r.get(k) is not None for r in results)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenarios", default=",".join(SCENARIOS))
    parser.add_argument("--seeds", default="1,2,3")
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--real", action="store_true", help="also ../shared/data (if present)")
    parser.add_argument("--no-synthetic", action="store_true")
    parser.add_argument("--cache", default=os.path.join(REPO, "build", "bench"))
    parser.add_argument("--config", default="")
    args = parser.parse_args()
    header = ("| sequence | ATE on [m] | ATE off [m] | off/on | RPE on [m/s] | tracked | coverage | "
              "dyn. precision | dyn. recall | static wrongly dyn. | labelled dyn. | total [ms] | "
              "SPD [ms] |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    print(header)
    started = time.time()
    seeds = [int(s) for s in args.seeds.split(",") if s]
    if not args.no_synthetic:
        for scenario in [s for s in args.scenarios.split(",") if s]:
            per_seed = {True: [], False: []}
            for seed in seeds:
                folder = render(scenario, seed, args.frames, args.cache)
                out_dir = os.path.join(args.cache, "runs", os.path.basename(folder))
                os.makedirs(out_dir, exist_ok=True)
                for on in (True, False):
                    per_seed[on].append(evaluate(folder, "", on, out_dir, args.config))
            print(row(f"synthetic {scenario} (seeds {args.seeds})", mean_of(per_seed[True]),
                      mean_of(per_seed[False])), flush=True)
    if args.real:
        for name, folder in [("Bonn crowd 300-599", "bonn_crowd_frames300-599"),
                             ("TUM fr1/desk 9 frames", "tum_fr1_desk_9frames")]:
            path = os.path.join(SHARED, folder)
            if not os.path.isdir(path):
                continue
            out_dir = os.path.join(args.cache, "runs", folder)
            os.makedirs(out_dir, exist_ok=True)
            results = {on: evaluate(path, os.path.join(path, "camera.yaml"), on, out_dir,
                                    args.config) for on in (True, False)}
            print(row(name, results[True], results[False]), flush=True)
    print(f"\n(benchmark wall time {time.time() - started:.0f} s, {os.cpu_count()} cores)")


if __name__ == "__main__":
    main()
