#!/usr/bin/env python3
"""Benchmark: accuracy, segmentation and speed of dslam (default parameters) beside two variants
from the same run: the back end on (local mapping after keyframes; off by default) and static
point determination off (the static-world baseline).
Prints a Markdown table for BENCHMARKS.md.

Synthetic scenarios are rendered once per seed into --cache (seeds 1, 2, 3 averaged); with
--real, every sequence found in ../shared/data. With --reference-bin (the devel/lib/dslam folder
of another build, e.g. a `git worktree` of an older commit built with scripts/setup.sh), that
build's defaults run on the same sequences in the same invocation: the column "ATE reference".
--jobs runs that many dslam_run_dataset processes at once (the per-frame times then share the
cores). Usage:
  scripts/benchmark.py [--scenarios walking,static_room] [--seeds 1,2,3] [--frames 300]
                       [--real] [--cache build/bench] [--config params.yaml]
                       [--reference-bin DIR] [--jobs 1]
"""
import argparse
import concurrent.futures
import json
import os
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dslam_tools import synth_cache  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WS = os.environ.get("DSLAM_WS", os.path.join(REPO, "build", "ws"))
BIN = os.path.join(WS, "devel", "lib", "dslam")
SHARED = os.path.join(os.path.dirname(REPO), "shared", "data")
SCENARIOS = ["walking", "walking_static", "close_person", "walking_halfsphere", "slow_box",
             "nonrigid_sheet", "static_room", "fast_rotation"]


def run(cmd):
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if proc.returncode != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{proc.stdout}\n{proc.stderr}")
    return proc.stdout


def render(scenario, seed, frames, cache, bin_dir=BIN):
    """The folder of (scenario, seed) in `cache`, rendered once by bin_dir's dslam_synth."""
    folder = os.path.join(cache, f"{scenario}_f{frames}_s{seed}")
    if not synth_cache.is_current(folder, scenario):
        run([os.path.join(bin_dir, "dslam_synth"), "--scenario", scenario, "--frames", str(frames),
             "--seed", str(seed), "--output", folder])
    return folder


# The variants of every row, run in the same invocation: dslam, and the two baselines.
VARIANTS = {
    "dslam": [],                                   # the defaults (back end off, docs/how-it-works.md)
    "backend_on": ["--backend", "on"],             # local mapping after keyframes
    "static_off": ["--static-points", "off"],      # static-world baseline
}


def evaluate(folder, camera, variant, out_dir, config, run_bin=BIN, eval_bin=BIN):
    """Runs run_bin's dslam_run_dataset (`variant`; "reference": the defaults) on `folder` and
    eval_bin's dslam_eval on its trajectory (outputs in out_dir); returns the run's summary and the
    evaluation together."""
    traj = os.path.join(out_dir, f"trajectory_{variant}.txt")
    summary = os.path.join(out_dir, f"summary_{variant}.json")
    loops = os.path.join(out_dir, f"loops_{variant}.txt")  # empty without loop closing
    cmd = [os.path.join(run_bin, "dslam_run_dataset"), "--dataset", folder, "--trajectory", traj,
           "--status", os.path.join(out_dir, f"status_{variant}.csv"), "--summary", summary,
           "--loops", loops, "--quiet"] + VARIANTS.get(variant, [])
    if camera:
        cmd += ["--camera", camera]
    if config:
        cmd += ["--config", config]
    run(cmd)
    metrics = os.path.join(out_dir, f"eval_{variant}.json")
    ev = [os.path.join(eval_bin, "dslam_eval"), "--groundtruth", os.path.join(folder, "groundtruth.txt"),
          "--trajectory", traj, "--frames", os.path.join(folder, "rgb.txt"), "--json", metrics,
          "--loops", loops]
    ev += ["--camera", camera or os.path.join(folder, "camera.yaml")]
    run(ev)
    with open(summary) as f:
        result = json.load(f)
    with open(metrics) as f:
        result.update(json.load(f))
    return result


def fmt(value, digits=4):
    return "n/a" if value is None else f"{value:.{digits}f}"


HEADER = ("| sequence | ATE [m] | ATE reference [m] | ATE back end on [m] | ATE static points off [m] | "
          "step median / max [mm] | step back end on [mm] | "
          "RPE [m/s] | RPE [deg/s] | RPE [deg/s] back end on | tracked | tracked back end on | "
          "dyn. precision | dyn. recall | static wrongly dyn. | labelled dyn. | "
          "back end on: dyn. precision / recall / static wrongly dyn. | "
          "frame [ms] | frame back end on [ms] | BA [ms] median / p95 | BA keyframes / points | "
          "window SPD [ms] median / p95 | window SPD points / unmarked | "
          "back end on: loops closed / false | back end on: loop [ms] median / p95 |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
          "---|---|")


def loops(result):
    """loops closed / false (dslam_eval --loops) | loop work per keyframe median / p95 [ms];
    '-' for a run without loop closing (no median_loop_ms: mean_of keeps numbers only)."""
    if "median_loop_ms" not in result:
        return "- | -"
    return (f"{result.get('loops', 0):.0f} / {result.get('false_loops', 0):.0f} | "
            f"{result.get('median_loop_ms', 0.0):.1f} / {result.get('p95_loop_ms', 0.0):.1f}")


def has_movers(result):
    """Whether the scene of a run's summary has truly dynamic candidate points."""
    return result.get("true_dynamic", 0) + result.get("missed_dynamic", 0) > 0


SEGMENTATION_DIGITS = (("dynamic_precision", 3), ("dynamic_recall", 3), ("false_dynamic_rate", 4))


def segmentation_scores(result, moving):
    """The scored segmentation numbers of a run: precision and recall only where the scene has
    movers, the share of static points wrongly dynamic where it has truth."""
    names = ("dynamic_precision", "dynamic_recall", "false_dynamic_rate") if moving \
        else ("false_dynamic_rate",)
    return {name: result[name] for name in names if name in result}


def segmentation(result, moving):
    """precision | recall | static wrongly dynamic, '-' where the scene has no truth or movers."""
    scores = segmentation_scores(result, moving)
    return " | ".join(f"{scores[name]:.{digits}f}" if name in scores else "-"
                      for name, digits in SEGMENTATION_DIGITS)


def steps(result):
    """median / largest frame-to-frame step of the camera centre [mm]."""
    return f"{result['step_median_m'] * 1000:.1f} / {result['step_max_m'] * 1000:.1f}"


def row(name, results):
    on, backend, no_static = (results[v] for v in ("dslam", "backend_on", "static_off"))
    moving = has_movers(on)
    seg = segmentation(on, moving) + f" | {on['labelled_dynamic_share']:.4f}"
    seg += " | " + segmentation(backend, moving).replace(" | ", " / ")
    tracked = on["frames_with_pose"] / max(on["frames"], 1)
    tracked_backend = backend["frames_with_pose"] / max(backend["frames"], 1)
    reference = f"{results['reference']['ate_rmse_m']:.4f}" if "reference" in results else "-"
    return (f"| {name} | {on['ate_rmse_m']:.4f} | {reference} | {backend['ate_rmse_m']:.4f} | "
            f"{no_static['ate_rmse_m']:.4f} | {steps(on)} | {steps(backend)} | "
            f"{fmt(on.get('rpe_trans_rmse_m_per_s'))} | "
            f"{fmt(on.get('rpe_rot_rmse_deg_per_s'), 2)} | "
            f"{fmt(backend.get('rpe_rot_rmse_deg_per_s'), 2)} | {tracked:.3f} | "
            f"{tracked_backend:.3f} | {seg} | {on['median_frame_ms']:.1f} | "
            f"{backend['median_frame_ms']:.1f} | "
            f"{backend['median_ba_ms']:.1f} / {backend['p95_ba_ms']:.1f} | "
            f"{backend['median_ba_keyframes']:.0f} / {backend['median_ba_points']:.0f} | "
            f"{backend['median_spd_ms']:.1f} / {backend['p95_spd_ms']:.1f} | "
            f"{backend['median_spd_points']:.0f} / {backend['median_spd_unmarked']:.0f} | "
            f"{loops(backend)} |")


def mean_of(results):
    keys = [k for k, v in results[0].items() if isinstance(v, (int, float)) and not isinstance(v, bool)]
    return {k: statistics.mean(r[k] for r in results if r.get(k) is not None)
            for k in keys if all(r.get(k) is not None for r in results)}


def run_all(jobs, tasks):
    """Runs evaluate(*task) for every task, `jobs` at a time; returns the results in task order."""
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        return list(pool.map(lambda task: evaluate(*task), tasks))


def real_sequences():
    """(name, folder) of every sequence in ../shared/data (a folder with rgb.txt)."""
    if not os.path.isdir(SHARED):
        return []
    return [(name, os.path.join(SHARED, name)) for name in sorted(os.listdir(SHARED))
            if os.path.isfile(os.path.join(SHARED, name, "rgb.txt"))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenarios", default=",".join(SCENARIOS))
    parser.add_argument("--seeds", default="1,2,3")
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--real", action="store_true", help="also ../shared/data (if present)")
    parser.add_argument("--no-synthetic", action="store_true")
    parser.add_argument("--cache", default=os.path.join(REPO, "build", "bench"))
    parser.add_argument("--config", default="")
    parser.add_argument("--reference-bin", default="", help="another build's devel/lib/dslam")
    parser.add_argument("--jobs", type=int, default=1)
    args = parser.parse_args()
    variants = list(VARIANTS) + (["reference"] if args.reference_bin else [])

    def tasks(folder, camera, out_dir):
        return [(folder, camera, v, out_dir, args.config,
                 args.reference_bin if v == "reference" else BIN) for v in variants]

    print(HEADER)
    started = time.time()
    seeds = [int(s) for s in args.seeds.split(",") if s]
    if not args.no_synthetic:
        for scenario in [s for s in args.scenarios.split(",") if s]:
            all_tasks = []
            for seed in seeds:
                folder = render(scenario, seed, args.frames, args.cache)
                out_dir = os.path.join(args.cache, "runs", os.path.basename(folder))
                os.makedirs(out_dir, exist_ok=True)
                all_tasks += tasks(folder, "", out_dir)
            results = run_all(args.jobs, all_tasks)
            per_seed = {v: results[i::len(variants)] for i, v in enumerate(variants)}
            means = {variant: mean_of(runs) for variant, runs in per_seed.items()}
            print(row(f"synthetic {scenario} (seeds {args.seeds})", means), flush=True)
    if args.real:
        for name, path in real_sequences():
            out_dir = os.path.join(args.cache, "runs", name)
            os.makedirs(out_dir, exist_ok=True)
            results = run_all(args.jobs, tasks(path, os.path.join(path, "camera.yaml"), out_dir))
            print(row(name, dict(zip(variants, results))), flush=True)
    print(f"\n(benchmark wall time {time.time() - started:.0f} s, {os.cpu_count()} cores, "
          f"{args.jobs} jobs)")


if __name__ == "__main__":
    main()
