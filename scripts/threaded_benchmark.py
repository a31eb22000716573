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
import json
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark import BIN, REPO, render, run  # noqa: E402

DYNAMIC = ["walking", "walking_static", "close_person", "walking_halfsphere", "slow_box",
           "nonrigid_sheet"]


def ate_m(bin_dir, folder, trajectory):
    """ATE RMSE [m] of `trajectory` by bin_dir's dslam_eval (its --json output)."""
    metrics = trajectory + ".eval.json"
    run([os.path.join(bin_dir, "dslam_eval"), "--groundtruth",
         os.path.join(folder, "groundtruth.txt"), "--trajectory", trajectory,
         "--frames", os.path.join(folder, "rgb.txt"),
         "--camera", os.path.join(folder, "camera.yaml"), "--json", metrics])
    with open(metrics) as f:
        return json.load(f)["ate_rmse_m"]


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
    parser.add_argument("--bin", default=BIN)
    args = parser.parse_args()
    print("| sequence | sync ATE [mm] | threaded ATE [mm] | median / sync | "
          "sync refined [mm] | threaded refined [mm] | median / sync |\n"
          "|---|---|---|---|---|---|---|")
    started = time.time()
    ratios = []
    for scenario in [s for s in args.scenarios.split(",") if s]:
        for seed in [int(s) for s in args.seeds.split(",") if s]:
            folder = render(scenario, seed, args.frames, args.cache, args.bin)
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
