"""The pure parts of scripts/speed_benchmark.py: the numbers of one dslam_run_dataset run (from
its summary JSON and status CSV), the median over rounds, the Markdown table, and the peak
memory of a child process (os.wait4's rusage)."""

import os
import subprocess
import time

from dslam_tools.stats import median, quantile

# Goals the table states beside its columns (the project's speed issue).
GOAL_TRACKING_RATIO = 0.5  # current median tracking time / reference median total time
GOAL_P95_OVER_MEDIAN = 1.5  # current p95 tracking time / its median
GOAL_MAX_BACKLOG = 1  # [keyframes] queued for the back end and not started
GOAL_PEAK_RSS_MIB = 150.0


def backend_run_ms(rows):
    """[ms] Back-end time (window static point determination + local BA) of every run that the
    status CSV rows report (rows with ba_ms + spd_ms > 0)."""
    times = [float(r["ba_ms"]) + float(r["spd_ms"]) for r in rows]
    return [t for t in times if t > 0.0]


def keyframe_intervals_ms(rows, rate_hz):
    """[ms] Intervals between consecutive keyframes at the feeding rate: frame-index difference
    of consecutive rows with keyframe == 1, times 1000 / rate_hz."""
    frames = [int(r["frame"]) for r in rows if r["keyframe"] == "1"]
    return [(b - a) * 1000.0 / rate_hz for a, b in zip(frames, frames[1:])]


def current_metrics(summary, rows, rate_hz):
    """Numbers of one run of the current dslam_run_dataset (--threads --rate --backend on)."""
    median_ms = summary["median_tracking_ms"]
    runs = backend_run_ms(rows)
    return {
        "tracking_ms": median_ms,
        "p95_tracking_ms": summary["p95_tracking_ms"],
        "p95_over_median": summary["p95_tracking_ms"] / median_ms if median_ms > 0 else None,
        "backend_p95_ms": quantile(runs, 0.95),
        "backend_runs": summary.get("backend_runs", len(runs)),
        "keyframes": sum(1 for r in rows if r["keyframe"] == "1"),
        "keyframe_interval_ms": median(keyframe_intervals_ms(rows, rate_hz)),
        "max_backlog": summary["max_backlog"],
        "frames_with_pose": summary["frames_with_pose"],
        "frames": summary["frames"],
    }


def reference_metrics(summary):
    """Numbers of one run of the reference dslam_run_dataset (front end only, no threads): its
    median per-frame total time is its tracking time."""
    return {
        "tracking_ms": summary["median_total_ms"],
        "frames_with_pose": summary["frames_with_pose"],
        "frames": summary["frames"],
    }


# Keys combined with the maximum over rounds (worst case); every other number: the median.
MAX_OVER_ROUNDS = ("max_backlog", "peak_rss_mib")


def combine_rounds(runs):
    """One dict from the per-round dicts of one sequence and program: for each key the median
    over the rounds that have a number (None if none has), the maximum for MAX_OVER_ROUNDS."""
    keys = sorted({key for run in runs for key in run})
    combined = {}
    for key in keys:
        values = [run[key] for run in runs if run.get(key) is not None]
        if not values:
            combined[key] = None
        elif key in MAX_OVER_ROUNDS:
            combined[key] = max(values)
        else:
            combined[key] = median(values)
    return combined


def fmt(value, digits=1):
    """A number with `digits` decimals, or "n/a" for None."""
    return "n/a" if value is None else f"{value:.{digits}f}"


def ratio(numerator, denominator):
    """numerator / denominator, None when either is missing or the denominator is not > 0."""
    if numerator is None or denominator is None or denominator <= 0:
        return None
    return numerator / denominator


def table_header(reference_label):
    """The Markdown header of the table (two lines)."""
    columns = [
        "sequence", f"{reference_label} median total [ms]", "current median tracking [ms]",
        f"ratio (goal <= {GOAL_TRACKING_RATIO})",
        f"current p95 / median (goal <= {GOAL_P95_OVER_MEDIAN})",
        "back-end p95 per run [ms]", "median keyframe interval [ms]",
        "back-end runs / keyframes", f"max backlog (goal <= {GOAL_MAX_BACKLOG})",
        f"peak RSS [MiB] current / {reference_label} (goal <= {GOAL_PEAK_RSS_MIB:.0f})",
        f"ATE [m] current / {reference_label}",
    ]
    return "| " + " | ".join(columns) + " |\n|" + "---|" * len(columns)


def table_row(sequence, current, reference):
    """One Markdown row from the combined numbers of both programs on `sequence`."""
    cells = [
        sequence,
        fmt(reference.get("tracking_ms")),
        fmt(current.get("tracking_ms")),
        fmt(ratio(current.get("tracking_ms"), reference.get("tracking_ms")), 2),
        fmt(current.get("p95_over_median"), 2),
        fmt(current.get("backend_p95_ms")),
        fmt(current.get("keyframe_interval_ms")),
        f"{fmt(current.get('backend_runs'), 0)} / {fmt(current.get('keyframes'), 0)}",
        fmt(current.get("max_backlog"), 0),
        f"{fmt(current.get('peak_rss_mib'))} / {fmt(reference.get('peak_rss_mib'))}",
        f"{fmt(current.get('ate_m'), 4)} / {fmt(reference.get('ate_m'), 4)}",
    ]
    return "| " + " | ".join(cells) + " |"


def kib_to_mib(kib):
    """[MiB] from [KiB] (Linux reports ru_maxrss in KiB)."""
    return kib / 1024.0


def run_measured(cmd, log_path):
    """Runs `cmd` with stdout and stderr to `log_path`; returns (exit code, peak resident set
    size of the child [MiB] from os.wait4's rusage, wall time [s])."""
    start = time.monotonic()
    with open(log_path, "w") as log:
        proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)  # reaped here, not by Popen
    return proc.returncode, kib_to_mib(usage.ru_maxrss), time.monotonic() - start
