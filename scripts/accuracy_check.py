#!/usr/bin/env python3
"""Accuracy check of a change that cannot keep the trajectories identical (issue 13): the current
dslam_run_dataset against a reference build of an older commit on the synthetic scenarios x seeds
(rendered once by the reference's dslam_synth, both builds run on the same renders) and on
../shared/data's Bonn crowd 300-599 and TUM desk 9 frames when present. ATE comes from the
current dslam_eval for both builds, the segmentation scores from the runs' summaries (as
scripts/benchmark.py). Prints Markdown: a table per sequence (ATE before/after, difference,
byte-identical trajectory, segmentation), the ATE sums over the seeds per scenario, and the
verdict on each criterion of the issue. Exit status 0 unless a command fails (it is a report).

The reference is built once into build/reference/<commit>-ws (speed_benchmark.py's
prepare_reference); renders and runs go under --cache/<reference hash>/, and the reference's runs
are reused when they are there. Usage:
  scripts/accuracy_check.py --reference COMMIT [--current-bin DIR] [--seeds 1-5]
      [--scenarios walking,static_room] [--frames 300] [--cache build/accuracy]
      [--backend on|off] [--no-build]
"""
import argparse
import filecmp
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchmark  # noqa: E402  (render, evaluate, segmentation as its tables have them)
import speed_benchmark  # noqa: E402  (prepare_reference, prepare_current, shared data)

REAL = ("bonn_crowd_frames300-599", "tum_fr1_desk_9frames")
BONN = REAL[0]
SUM_TOLERANCE = 0.03  # relative change of a scenario's ATE sum over the seeds
WORSE_MIN_M, WORSE_SHARE = 0.001, 0.10  # a sequence may get worse by max(1 mm, 10 %)
BONN_WORSE_M = 0.002
SEGMENTATION_POINTS = 0.02  # 2 points of a score in [0, 1]
SCORE_NAMES = {"dynamic_precision": "dyn. precision", "dynamic_recall": "dyn. recall",
               "false_dynamic_rate": "static wrongly dyn."}


def parse_seeds(text):
    """'1-5' -> [1, 2, 3, 4, 5]; '1,3' -> [1, 3]; '1-2,5' -> [1, 2, 5]."""
    seeds = []
    for part in filter(None, text.split(",")):
        first, _, last = part.partition("-")
        seeds += range(int(first), int(last or first) + 1)
    return seeds


def sum_change(before, after):
    """Relative change of a sum; 0 when both are 0."""
    return (after - before) / before if before else (0.0 if after == before else float("inf"))


def scenario_sums(rows):
    """{scenario: (ATE sum before, after) [m]} over the synthetic rows, in the rows' order."""
    sums = {}
    for row in rows:
        if row["scenario"]:
            before, after = sums.get(row["scenario"], (0.0, 0.0))
            sums[row["scenario"]] = (before + row["before"]["ate_rmse_m"],
                                     after + row["after"]["ate_rmse_m"])
    return sums


def ate_difference(row):
    return row["after"]["ate_rmse_m"] - row["before"]["ate_rmse_m"]


def segmentation_offences(row):
    """'name: score -0.031' for each score of the row that moved by more than 2 points."""
    before = benchmark.segmentation_scores(row["before"], row["moving"])
    after = benchmark.segmentation_scores(row["after"], row["moving"])
    return [f"{row['name']}: {SCORE_NAMES[key]} {after[key] - before[key]:+.3f}"
            for key in before if key in after
            and abs(after[key] - before[key]) > SEGMENTATION_POINTS + 1e-12]


def verdicts(rows):
    """[(criterion, passed, offenders)] for the criteria of issue 13; a criterion without rows
    (e.g. Bonn absent) passes with the offender list ['not measured']."""
    sums = [f"{name}: {100 * sum_change(b, a):+.1f} %" for name, (b, a) in
            scenario_sums(rows).items() if abs(sum_change(b, a)) > SUM_TOLERANCE + 1e-12]
    worse = [f"{row['name']}: {1000 * ate_difference(row):+.1f} mm" for row in rows
             if ate_difference(row) > max(WORSE_MIN_M, WORSE_SHARE * row["before"]["ate_rmse_m"])]
    bonn = [row for row in rows if row["name"] == BONN]
    bonn_worse = [f"{BONN}: {1000 * ate_difference(row):+.1f} mm" for row in bonn
                  if ate_difference(row) > BONN_WORSE_M]
    segmentation = [text for row in rows for text in segmentation_offences(row)]
    return [
        ("sum of ATE over the seeds within 3 % of before, per scenario", not sums, sums),
        ("no sequence worse by more than max(1 mm, 10 %)", not worse, worse),
        ("shared Bonn segment no worse by more than 2 mm", not bonn_worse,
         bonn_worse if bonn else ["not measured"]),
        ("segmentation scores within 2 points (0.02)", not segmentation, segmentation),
    ]


def sequence_table(rows):
    lines = ["| sequence | ATE before [m] | ATE after [m] | difference [mm] | identical | "
             "segmentation before (precision / recall / static wrongly dyn.) | after |",
             "|---|---|---|---|---|---|---|"]
    for row in rows:
        seg = [benchmark.segmentation(row[side], row["moving"]).replace(" | ", " / ")
               for side in ("before", "after")]
        lines.append(f"| {row['name']} | {row['before']['ate_rmse_m']:.5f} | "
                     f"{row['after']['ate_rmse_m']:.5f} | {1000 * ate_difference(row):+.2f} | "
                     f"{'yes' if row['identical'] else 'no'} | {seg[0]} | {seg[1]} |")
    return lines


def scenario_table(rows):
    lines = ["| scenario | ATE sum before [m] | ATE sum after [m] | change [%] |",
             "|---|---|---|---|"]
    for name, (before, after) in scenario_sums(rows).items():
        lines.append(f"| {name} | {before:.5f} | {after:.5f} | "
                     f"{100 * sum_change(before, after):+.2f} |")
    return lines


def verdict_lines(rows):
    identical = sum(row["identical"] for row in rows)
    lines = [f"- trajectories byte-identical: {identical} of {len(rows)}"]
    for criterion, passed, offenders in verdicts(rows):
        lines.append(f"- {'PASS' if passed else 'FAIL'}: {criterion}"
                     + (f" ({'; '.join(offenders)})" if offenders else ""))
    return lines


def sequences(args, ref_bin, cache):
    """[(name, scenario or None, folder, camera)]: the renders, then the shared data present."""
    known = [line.split()[0] for line in
             benchmark.run([os.path.join(ref_bin, "dslam_synth"), "--list"]).splitlines() if line]
    found = []
    for scenario in filter(None, args.scenarios.split(",")):
        if scenario not in known:
            print(f"skipped {scenario}: the reference's dslam_synth does not know it",
                  file=sys.stderr)
            continue
        for seed in parse_seeds(args.seeds):
            folder = benchmark.render(scenario, seed, args.frames, cache, ref_bin)
            found.append((os.path.basename(folder), scenario, folder, ""))
    for name in REAL:
        folder = os.path.join(speed_benchmark.SHARED, name)
        if os.path.isdir(folder):
            found.append((name, None, folder, os.path.join(folder, "camera.yaml")))
    return found


def run_side(folder, camera, variant, out_dir, run_bin, eval_bin, reuse):
    """One build's run and evaluation of a sequence; reuses a finished one when `reuse`."""
    files = [os.path.join(out_dir, f"{kind}_{variant}.json") for kind in ("summary", "eval")]
    if not (reuse and all(os.path.exists(path) for path in files)):
        os.makedirs(out_dir, exist_ok=True)
        return benchmark.evaluate(folder, camera, variant, out_dir, "", run_bin, eval_bin)
    result = {}
    for path in files:
        with open(path) as handle:
            result.update(json.load(handle))
    return result


def compare(sequence, bins, root, variant):
    """The row of one sequence: both builds' results and whether the trajectories are equal."""
    name, scenario, folder, camera = sequence
    sides = {}
    for side, reuse in (("before", True), ("after", False)):
        out_dir = os.path.join(root, side, name)
        sides[side] = run_side(folder, camera, variant, out_dir, bins[side], bins["after"], reuse)
    trajectories = [os.path.join(root, side, name, f"trajectory_{variant}.txt")
                    for side in ("before", "after")]
    print(f"  {name}: ATE {sides['before']['ate_rmse_m']:.5f} -> "
          f"{sides['after']['ate_rmse_m']:.5f} m", file=sys.stderr, flush=True)
    return dict(name=name, scenario=scenario, before=sides["before"], after=sides["after"],
                moving=benchmark.has_movers(sides["before"]),
                identical=filecmp.cmp(*trajectories, shallow=False))


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reference", required=True, help="commit of the 'before' build")
    parser.add_argument("--current-bin", default="",
                        help="bin folder of the 'after' build (default: build/ws's, built)")
    parser.add_argument("--seeds", default="1-5")
    parser.add_argument("--scenarios", default=",".join(benchmark.SCENARIOS))
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--cache", default=os.path.join(speed_benchmark.REPO, "build", "accuracy"))
    parser.add_argument("--backend", choices=("on", "off"), default="off",
                        help="on: both builds run with --backend on; off: their defaults")
    parser.add_argument("--no-build", action="store_true", help="use build/ws as it is")
    return parser.parse_args()


def main():
    args = parse_args()
    ref_bin, ref_full, _ = speed_benchmark.prepare_reference(
        args.reference, ("dslam_run_dataset", "dslam_synth"))
    cur_bin = args.current_bin or speed_benchmark.prepare_current(not args.no_build)
    cache = os.path.join(args.cache, ref_full[:12])
    variant = "backend_on" if args.backend == "on" else "dslam"
    bins = {"before": ref_bin, "after": cur_bin}
    rows = [compare(sequence, bins, os.path.join(cache, "runs"), variant)
            for sequence in sequences(args, ref_bin, os.path.join(cache, "sequences"))]
    current = speed_benchmark.git("rev-parse", "HEAD")
    dirty = speed_benchmark.git("status", "--porcelain", "--untracked-files=no")
    print("\n".join([
        f"before: {args.reference} ({ref_full}); after: {cur_bin} (checkout {current}"
        f"{', with uncommitted changes' if dirty else ''}); dslam_run_dataset "
        f"{'--backend on' if args.backend == 'on' else 'defaults (back end off)'}; seeds "
        f"{args.seeds}, {args.frames} frames", ""]
        + sequence_table(rows) + [""] + scenario_table(rows) + [""] + verdict_lines(rows)))


if __name__ == "__main__":
    main()
