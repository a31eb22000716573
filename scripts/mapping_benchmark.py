#!/usr/bin/env python3
"""Mapping benchmark: the static map and the moving objects of dslam_run_dataset against the
synthetic truth of dslam_synth. For every scenario and seed it renders the sequence once into
--cache (with objects.txt and depth_true/), runs
  dslam_run_dataset --dataset D --trajectory T --map M --map-unmasked U --objects O --summary S
then dslam_eval_objects (found share, centroid and velocity error medians, false share, id
switches) and dslam_eval_map on the masked and the unmasked map (ghost share, static coverage),
and prints a Markdown table per scenario (one row per seed and their mean) and a table of the
scenario means. Usage:
  scripts/mapping_benchmark.py [--scenarios walking,static_room] [--seeds 1 2 3] [--frames 300]
                               [--cache build/mapping_bench] [--config params.yaml]
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark import run  # noqa: E402  (exits with the output of a failed command)
from dslam_tools import mapping_report, synth_cache  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WS = os.environ.get("DSLAM_WS", os.path.join(REPO, "build", "ws"))
BIN = os.path.join(WS, "devel", "lib", "dslam")
TRUTH_FILES = ("groundtruth.txt", "objects.txt", "depth_true.txt")


def render(scenario, seed, frames, cache):
    """The folder of (scenario, seed), rendered unless it already holds the truth files (folders
    rendered before objects.txt and depth_true/ existed are rendered again)."""
    folder = os.path.join(cache, f"{scenario}_f{frames}_s{seed}")
    if not synth_cache.is_current(folder, scenario, TRUTH_FILES):
        run([os.path.join(BIN, "dslam_synth"), "--scenario", scenario, "--frames", str(frames),
             "--seed", str(seed), "--output", folder])
    return folder


def parse_seeds(values):
    """Seeds given as separate arguments and/or comma-separated: ['1', '2,3'] -> [1, 2, 3]."""
    return [int(part) for value in values for part in value.split(",") if part]


def parse_args(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenarios", default=",".join(mapping_report.SCENARIOS),
                        help="comma-separated dslam_synth scenarios")
    parser.add_argument("--seeds", nargs="+", default=["1", "2", "3"],
                        help="seeds, separate or comma-separated (default 1 2 3)")
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--cache", default=os.path.join(REPO, "build", "mapping_bench"))
    parser.add_argument("--config", default="", help="dslam parameters (YAML) for the runs")
    args = parser.parse_args(argv)
    args.seeds = parse_seeds(args.seeds)
    args.scenarios = [s for s in args.scenarios.split(",") if s]
    return args


def measure(scenario, seed, args):
    folder = render(scenario, seed, args.frames, args.cache)
    out_dir = os.path.join(args.cache, "runs", os.path.basename(folder))
    os.makedirs(out_dir, exist_ok=True)
    paths = mapping_report.run_paths(out_dir)
    extra = ["--config", args.config] if args.config else []
    for cmd in mapping_report.run_commands(BIN, folder, paths, extra):
        run(cmd)
    return mapping_report.load_run(paths)


def main(argv=None):
    args = parse_args(argv)
    started = time.time()
    scenario_means = []
    for scenario in args.scenarios:
        runs = [measure(scenario, seed, args) for seed in args.seeds]
        print(mapping_report.scenario_table(scenario, args.seeds, runs) + "\n", flush=True)
        scenario_means.append((scenario, mapping_report.mean_numbers(runs)))
    print(mapping_report.summary_table(scenario_means))
    print(f"\n(mapping benchmark wall time {time.time() - started:.0f} s, {os.cpu_count()} cores)")


if __name__ == "__main__":
    main()
