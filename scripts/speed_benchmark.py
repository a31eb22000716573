#!/usr/bin/env python3
"""Speed benchmark: the current dslam_run_dataset (--threads --rate 30 --backend on) against a
reference build of an older commit (default cdfc860, the front end before the back end, which
runs as fast as it can: its per-frame total time is its tracking time) on the same sequences,
interleaved A B A B (A: reference, B: current). Prints a Markdown table for BENCHMARKS.md with
the ratios, the machine (cores, CPU model, load averages before and after) and the commits.

The reference is built once, from `git archive <commit>` into build/reference/<commit>, with that
tree's own scripts/setup.sh in the workspace build/reference/<commit>-ws (only dslam_run_dataset;
CCACHE_DIR from the environment is passed on). The current build is build/ws (or $DSLAM_WS),
brought up to date with scripts/setup.sh unless --no-build. Synthetic sequences are rendered once
by the current dslam_synth into build/speed_bench/cache. Usage:
  scripts/speed_benchmark.py [--reference-commit cdfc860] [--rounds 2]
      [--sequences bonn_crowd_frames300-599,walking,static_room] [--out build/speed_bench/runs]
      [--mapping]
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dslam_tools import speed_report, synth_cache  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WS = os.environ.get("DSLAM_WS", os.path.join(REPO, "build", "ws"))


def shared_data():
    """../shared/data beside this checkout, or beside the main checkout when this one is a git
    worktree elsewhere (its common .git folder is the main checkout's)."""
    common = subprocess.run(["git", "-C", REPO, "rev-parse", "--path-format=absolute",
                             "--git-common-dir"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                            text=True).stdout.strip()
    for checkout in [REPO] + ([os.path.dirname(common)] if common else []):
        path = os.path.join(os.path.dirname(checkout), "shared", "data")
        if os.path.isdir(path):
            return path
    return os.path.join(os.path.dirname(REPO), "shared", "data")


SHARED = shared_data()
RATE_HZ = 30.0
SYNTH_FRAMES, SYNTH_SEED = 300, 1
CURRENT_ARGS = ["--threads", "--rate", f"{RATE_HZ:g}", "--backend", "on"]
CURRENT_TARGETS = ["dslam_run_dataset_main", "dslam_synth_main", "dslam_eval_main"]


def check_run(cmd, env=None):
    """Runs `cmd` (output captured); exits with its output when it fails."""
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          env=env)
    if proc.returncode != 0:
        sys.exit(f"failed ({proc.returncode}): {' '.join(cmd)}\n{proc.stdout[-4000:]}")
    return proc.stdout


def git(*args):
    return check_run(["git", "-C", REPO] + list(args)).strip()


def build_env(ws):
    """The environment for a setup.sh build into workspace `ws`: Debian's tools first."""
    env = dict(os.environ, DSLAM_WS=ws)
    env["PATH"] = "/usr/bin:/bin:/usr/sbin:/sbin:" + env.get("PATH", "")
    return env


def tool_target(tree, tool):
    """The catkin target that builds `tool` in source tree `tree`: older trees name the
    executable target after the tool (add_executable(dslam_run_dataset ...)), newer ones add
    _main (dslam_tool() in cmake/dslam_parts.cmake)."""
    pattern = f"add_executable({tool} "
    for folder, _, files in os.walk(tree):
        for name in files:
            if name == "CMakeLists.txt" or name.endswith(".cmake"):
                with open(os.path.join(folder, name)) as handle:
                    if pattern in handle.read():
                        return tool
    return tool + "_main"


def prepare_reference(commit, tools=("dslam_run_dataset",)):
    """Extracts the reference commit once and builds its `tools` unless all are built already;
    returns (bin folder, full hash, text on the build: its wall time, measured when it was built
    and kept in the workspace)."""
    full = git("rev-parse", "--verify", commit + "^{commit}")
    tree = os.path.join(REPO, "build", "reference", commit)
    ws = tree + "-ws"
    bin_dir = os.path.join(ws, "devel", "lib", "dslam")
    timing = os.path.join(ws, "reference_build_seconds.txt")
    if all(os.access(os.path.join(bin_dir, tool), os.X_OK) for tool in tools):
        seconds = "unknown"
        if os.path.exists(timing):
            with open(timing) as handle:
                seconds = handle.read().strip()
        return bin_dir, full, f"built before this run (its build took {seconds} s)"
    if not os.path.exists(os.path.join(tree, ".extracted")):
        os.makedirs(tree, exist_ok=True)
        archive = subprocess.Popen(["git", "-C", REPO, "archive", "--format=tar", full],
                                   stdout=subprocess.PIPE)
        subprocess.run(["tar", "-x", "-C", tree], stdin=archive.stdout, check=True)
        if archive.wait() != 0:
            sys.exit(f"git archive {full} failed")
        open(os.path.join(tree, ".extracted"), "w").close()
    os.makedirs(ws, exist_ok=True)
    print(f"building the reference {commit} in {ws} (once) ...", file=sys.stderr, flush=True)
    start = time.monotonic()
    check_run([os.path.join(tree, "scripts", "setup.sh")] + [tool_target(tree, tool)
                                                            for tool in tools], env=build_env(ws))
    seconds = f"{time.monotonic() - start:.0f}"
    with open(timing, "w") as handle:
        handle.write(seconds + "\n")
    return bin_dir, full, f"built in this run in {seconds} s"


def prepare_current(build):
    """Brings the current workspace up to date (unless `build` is False); returns its bin
    folder."""
    if build:
        print(f"building the current code in {WS} ...", file=sys.stderr, flush=True)
        check_run([os.path.join(REPO, "scripts", "setup.sh")] + CURRENT_TARGETS,
                  env=build_env(WS))
    return os.path.join(WS, "devel", "lib", "dslam")


def sequence_folder(name, bin_dir, cache):
    """The dataset folder of `name`: a folder of ../shared/data, else a scenario of dslam_synth
    rendered once into `cache`; None when it is neither (e.g. ../shared/data is absent)."""
    path = os.path.join(SHARED, name)
    if os.path.isdir(path):
        return path
    synth = os.path.join(bin_dir, "dslam_synth")
    scenarios = [line.split()[0] for line in check_run([synth, "--list"]).splitlines() if line]
    if name not in scenarios:
        return None
    folder = os.path.join(cache, f"{name}_f{SYNTH_FRAMES}_s{SYNTH_SEED}")
    if not synth_cache.is_current(folder, name):
        check_run([synth, "--scenario", name, "--frames", str(SYNTH_FRAMES), "--seed",
                   str(SYNTH_SEED), "--output", folder])
    return folder


def ate_m(eval_bin, folder, trajectory, json_path):
    """[m] ATE RMSE of `trajectory` against the folder's ground truth (current dslam_eval)."""
    check_run([os.path.join(eval_bin, "dslam_eval"), "--groundtruth",
               os.path.join(folder, "groundtruth.txt"), "--trajectory", trajectory, "--frames",
               os.path.join(folder, "rgb.txt"), "--camera", os.path.join(folder, "camera.yaml"),
               "--json", json_path])
    with open(json_path) as handle:
        return json.load(handle)["ate_rmse_m"]


MAPPING = False  # --mapping: the current runs also write the static map and the moving objects


def run_once(program, bin_dir, folder, stem, eval_bin):
    """One dslam_run_dataset run of `program` ("current" or "reference") on `folder`, outputs
    under the path prefix `stem`; returns its numbers. With --mapping the current run's tracking
    time is median_tracking_ms + median_objects_add_ms: the tracking thread hands each frame to
    the moving objects' own thread (--threads), the static map runs on the back-end thread."""
    cmd = [os.path.join(bin_dir, "dslam_run_dataset"), "--dataset", folder, "--camera",
           os.path.join(folder, "camera.yaml"), "--trajectory", stem + ".txt", "--summary",
           stem + ".json", "--status", stem + ".csv", "--quiet"]
    if program == "current":
        cmd += CURRENT_ARGS
        if MAPPING:
            cmd += ["--map", stem + "_map.pcd", "--objects", stem + "_objects.txt"]
    code, peak_mib, wall_s = speed_report.run_measured(cmd, stem + ".log")
    if code != 0:
        sys.exit(f"failed ({code}): {' '.join(cmd)}; see {stem}.log")
    with open(stem + ".json") as handle:
        summary = json.load(handle)
    if program == "current":
        with open(stem + ".csv") as handle:
            metrics = speed_report.current_metrics(summary, list(csv.DictReader(handle)), RATE_HZ)
        if MAPPING:
            metrics["tracking_ms"] += summary["median_objects_add_ms"]
    else:
        metrics = speed_report.reference_metrics(summary)
    metrics.update(peak_rss_mib=peak_mib, wall_s=wall_s,
                   ate_m=ate_m(eval_bin, folder, stem + ".txt", stem + "_eval.json"))
    return metrics


def machine():
    """Cores and CPU model of this machine."""
    model = "unknown"
    with open("/proc/cpuinfo") as handle:
        for line in handle:
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    return f"{os.cpu_count()} cores, {model}"


def load():
    return " ".join(f"{value:.2f}" for value in os.getloadavg())


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reference-commit", default="cdfc860")
    parser.add_argument("--rounds", type=int, default=2, help="A B pairs per sequence")
    parser.add_argument("--sequences", default="bonn_crowd_frames300-599,walking,static_room",
                        help="folders of ../shared/data or synthetic scenarios, comma-separated")
    parser.add_argument("--out", default=os.path.join(REPO, "build", "speed_bench", "runs"))
    parser.add_argument("--mapping", action="store_true",
                        help="current runs with --map and --objects (tracking time includes the "
                             "median time of handing each frame to the objects' thread)")
    parser.add_argument("--no-build", action="store_true",
                        help="use build/ws as it is (no scripts/setup.sh)")
    return parser.parse_args()


def run_sequence(name, folder, bins, rounds, out_dir):
    """A B A B ... on one sequence; returns {program: numbers combined over rounds} and the
    per-round numbers."""
    per_round = {"reference": [], "current": []}
    os.makedirs(os.path.join(out_dir, name), exist_ok=True)
    for round_index in range(1, rounds + 1):
        for program in ("reference", "current"):
            stem = os.path.join(out_dir, name, f"{program}_r{round_index}")
            per_round[program].append(run_once(program, bins[program], folder, stem,
                                               bins["current"]))
            print(f"  {name} round {round_index} {program}: "
                  f"{per_round[program][-1]['tracking_ms']:.1f} ms, "
                  f"load {load()}", file=sys.stderr, flush=True)
    combined = {p: speed_report.combine_rounds(runs) for p, runs in per_round.items()}
    return combined, per_round


def per_round_lines(name, per_round):
    """One line per round of the tracking medians of both programs (how much the rounds
    differ)."""
    return [f"- {name} round {i + 1}: reference {ref['tracking_ms']:.1f} ms, current "
            f"{cur['tracking_ms']:.1f} ms (p95 {cur['p95_tracking_ms']:.1f})"
            for i, (ref, cur) in enumerate(zip(per_round["reference"], per_round["current"]))]


def main():
    global MAPPING
    args = parse_args()
    MAPPING = args.mapping
    started, load_start = time.monotonic(), load()
    current_commit = git("rev-parse", "HEAD")
    dirty = " (with uncommitted changes)" if git("status", "--porcelain", "--untracked-files=no") \
        else ""
    ref_bin, ref_full, ref_build = prepare_reference(args.reference_commit)
    bins = {"reference": ref_bin, "current": prepare_current(not args.no_build)}
    cache = os.path.join(REPO, "build", "speed_bench", "cache")
    lines, notes, results = [], [], {}
    load_before = load()
    for name in [s for s in args.sequences.split(",") if s]:
        folder = sequence_folder(name, bins["current"], cache)
        if folder is None:
            notes.append(f"- {name}: skipped, neither a folder of {SHARED} (absent) nor a "
                         "synthetic scenario")
            continue
        combined, per_round = run_sequence(name, folder, bins, args.rounds, args.out)
        results[name] = {"combined": combined, "rounds": per_round}
        lines.append(speed_report.table_row(name, combined["current"], combined["reference"]))
        notes += per_round_lines(name, per_round)
    label = args.reference_commit
    report = "\n".join([
        f"current {current_commit}{dirty} vs reference {label} ({ref_full}); "
        f"current: dslam_run_dataset {' '.join(CURRENT_ARGS)}"
        f"{' --map M --objects O (tracking = median tracking + median objects add ms)' if MAPPING else ''}"
        "; reference: as fast as it runs",
        f"machine: {machine()}; load average (1/5/15 min): {load_start} at start, "
        f"{load_before} before the runs, {load()} after the runs",
        f"rounds: {args.rounds} (A B per sequence and round; medians over rounds, max backlog "
        f"and peak RSS: maximum over rounds); wall time {time.monotonic() - started:.0f} s",
        f"reference build (its scripts/setup.sh, dslam_run_dataset only): {ref_build}",
        "", speed_report.table_header(label)] + lines + [""] + notes)
    print(report)
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "report.md"), "w") as handle:
        handle.write(report + "\n")
    with open(os.path.join(args.out, "results.json"), "w") as handle:
        json.dump(results, handle, indent=1)


if __name__ == "__main__":
    main()
