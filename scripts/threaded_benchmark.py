#!/usr/bin/env python3
"""Threaded against synchronous back end: dslam_run_dataset --backend on, once synchronously and
--repeats times with the back end on its own thread (--threads --rate 30, frames fed at camera
rate), on synthetic scenarios and seeds (rendered once into --cache by dslam_synth). Prints a
Markdown table per sequence: the synchronous ATE, the threaded ATEs, their median and its ratio to
the synchronous one, and the same for the refined trajectory. Threaded runs depend on the
scheduler: run it on an otherwise idle machine. Usage:
  scripts/threaded_benchmark.py [--scenarios walking,close_person] [--seeds 1,2,3] [--repeats 3]
      [--frames 300] [--cache build/bench] [--bin build/ws/devel/lib/dslam]
"""
import argparse
import os
import statistics
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WS = os.environ.get("DSLAM_WS", os.path.join(REPO, "build", "ws"))
DYNAMIC = ["walking", "walking_static", "close_person", "walking_halfsphere", "slow_box",
           "nonrigid_sheet"]


def run(cmd):
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if proc.returncode != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{proc.stdout}\n{proc.stderr}")
    return proc.stdout


def ate_m(bin_dir, folder, trajectory):
    out = run([os.path.join(bin_dir, "dslam_eval"), "--groundtruth",
               os.path.join(folder, "groundtruth.txt"), "--trajectory", trajectory,
               "--frames", os.path.join(folder, "rgb.txt"),
               "--camera", os.path.join(folder, "camera.yaml")])
    for line in out.splitlines():
        if line.startswith("ATE RMSE"):
            return float(line.split()[-1])
    sys.exit(f"no ATE in dslam_eval's output for {trajectory}")


def run_once(bin_dir, folder, out_base, threaded):
    """(causal ATE, refined ATE) [m] of one --backend on run."""
    cmd = [os.path.join(bin_dir, "dslam_run_dataset"), "--dataset", folder, "--backend", "on",
           "--trajectory", out_base + ".txt", "--refined-trajectory", out_base + ".refined.txt",
           "--quiet"]
    if threaded:
        cmd += ["--threads", "--rate", "30"]
    run(cmd)
    return (ate_m(bin_dir, folder, out_base + ".txt"),
            ate_m(bin_dir, folder, out_base + ".refined.txt"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenarios", default=",".join(DYNAMIC))
    parser.add_argument("--seeds", default="1,2,3")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--cache", default=os.path.join(REPO, "build", "bench"))
    parser.add_argument("--bin", default=os.path.join(WS, "devel", "lib", "dslam"))
    args = parser.parse_args()
    print("| sequence | sync ATE [mm] | threaded ATE [mm] | median / sync | "
          "sync refined [mm] | threaded refined [mm] | median / sync |\n"
          "|---|---|---|---|---|---|---|")
    started = time.time()
    ratios = []
    for scenario in [s for s in args.scenarios.split(",") if s]:
        for seed in [int(s) for s in args.seeds.split(",") if s]:
            folder = os.path.join(args.cache, f"{scenario}_f{args.frames}_s{seed}")
            if not os.path.exists(os.path.join(folder, "groundtruth.txt")):
                run([os.path.join(args.bin, "dslam_synth"), "--scenario", scenario, "--frames",
                     str(args.frames), "--seed", str(seed), "--output", folder])
            out = os.path.join(args.cache, "threaded", os.path.basename(folder))
            os.makedirs(out, exist_ok=True)
            sync = run_once(args.bin, folder, os.path.join(out, "sync"), False)
            threaded = [run_once(args.bin, folder, os.path.join(out, f"threaded{r}"), True)
                        for r in range(args.repeats)]
            cells = []
            for k in (0, 1):
                values = [t[k] for t in threaded]
                median = statistics.median(values)
                ratio = median / sync[k] if sync[k] > 0 else float("nan")
                if k == 0:
                    ratios.append(ratio)
                cells += [f"{1000 * sync[k]:.1f}", " / ".join(f"{1000 * v:.1f}" for v in values),
                          f"{ratio:.3f}"]
            print(f"| {scenario} s{seed} | " + " | ".join(cells) + " |", flush=True)
    print(f"\nmedian of the causal ratios {statistics.median(ratios):.3f}; "
          f"within 5 %: {sum(abs(r - 1) <= 0.05 for r in ratios)} of {len(ratios)} "
          f"(wall time {time.time() - started:.0f} s, {os.cpu_count()} cores)")


if __name__ == "__main__":
    main()
