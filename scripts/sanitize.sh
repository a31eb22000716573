#!/usr/bin/env bash
# Builds dslam with a sanitizer in a workspace of its own and runs that sanitizer's checks; exit 0
# when it reported nothing in dslam code. Not part of scripts/test.sh: it is a second,
# instrumented build of dslam, and the runs are several times slower.
#
# Usage: scripts/sanitize.sh KIND
#   thread  ThreadSanitizer, workspace build/tsan: test_slam_threads (the back-end thread against
#           the synchronous mode, Reset and destruction with work queued), then
#           `dslam_run_dataset --threads --backend on` on $DSLAM_SANITIZE_FRAMES (80) frames of
#           the synthetic `walking` scenario, seed 1.
# A new kind (address, undefined) adds a case to `kind_settings` and, if it needs them, its own
# runs; cmake/dslam_parts.cmake already accepts DSLAM_SANITIZE=address|undefined.
#
# Every dslam library, tool and gtest gets -fsanitize=KIND -g -O1 (DSLAM_SANITIZE); the Debian
# libraries stay uninstrumented, and scripts/tsan.supp suppresses reports that lie entirely in
# them (each line justified there). Reports go to build/<ws>/reports/; a report with a frame in
# dslam (a `dslam::` function or a file of this repository) fails the run, any other report is
# listed. Environment: DSLAM_JOBS (2), DSLAM_SANITIZE_FRAMES (80).
set -euo pipefail
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
KIND="${1:-}"
FRAMES="${DSLAM_SANITIZE_FRAMES:-80}"

# Per kind: the workspace name, the runtime options variable and the suppressions file.
kind_settings() {
  case "$KIND" in
    thread)
      NAME=tsan OPTIONS_VAR=TSAN_OPTIONS SUPP="$REPO/scripts/tsan.supp"
      REPORT_MARK="WARNING: ThreadSanitizer:" ;;
    *)
      echo "usage: scripts/sanitize.sh thread" >&2
      exit 2 ;;
  esac
}
kind_settings
WS="$REPO/build/$NAME"
REPORTS="$WS/reports"
BIN="$WS/devel/lib/dslam"

echo "[sanitize] building $WS with DSLAM_SANITIZE=$KIND (log: $WS/build.log)"
DSLAM_WS="$WS" "$REPO/scripts/setup.sh" -DDSLAM_SANITIZE="$KIND" \
  dslam_run_dataset_main dslam_synth_main test_slam_threads > /dev/null
rm -rf "$REPORTS"
mkdir -p "$REPORTS"
# halt_on_error=0: every report of a run is written, to $REPORTS/<run>.<pid>; exitcode=0: the
# exit status is the program's own (a failing test), the reports are judged below.
# taskset: one CPU. Debian's OpenCV runs cv::parallel_for_ (dslam's ORB extraction in
# features.cpp, the renderer in synth/) on TBB worker threads, and TBB is not instrumented: TSan
# sees neither the hand-over of a loop to the workers nor the join before cv::parallel_for_
# returns, and reports the loop's data (measured on 45 frames of static_room with
# `dslam_run_dataset --threads --backend on`: 148 such reports, each with a thread created in
# libtbb.so.12, and 5.4 s/frame against 0.17 s). A suppression cannot express "a thread created
# by TBB" (GCC 12's TSan matches suppressions against the access stacks, whose TBB frames it
# cannot record). With one CPU, TBB starts no worker thread and the loops run on the calling
# thread; dslam's own threads (tracking, Slam's back end) stay separate threads, and TSan judges
# them by happens-before, not by simultaneous execution.
CPU="$(python3 -c 'import os; print(min(os.sched_getaffinity(0)))')"
failed_runs=0
run_sanitized() {
  local name=$1 code=0
  shift
  local options="suppressions=$SUPP print_suppressions=1 halt_on_error=0 exitcode=0"
  options+=" second_deadlock_stack=1 log_path=$REPORTS/$name"
  echo "[sanitize] $name: $*"
  env "$OPTIONS_VAR=$options" taskset -c "$CPU" "$@" > "$REPORTS/$name.out" 2>&1 ||
    code=$?
  echo "[sanitize] $name: exit status $code, last line: $(tail -n 1 "$REPORTS/$name.out")"
  if ((code != 0)); then failed_runs=$((failed_runs + 1)); fi
}

run_sanitized test_slam_threads "$BIN/test_slam_threads"
SEQUENCE="$WS/sequences/walking_f${FRAMES}_s1"
[[ -f "$SEQUENCE/groundtruth.txt" ]] || run_sanitized synth "$BIN/dslam_synth" \
  --scenario walking --frames "$FRAMES" --seed 1 --output "$SEQUENCE"
run_sanitized run_dataset "$BIN/dslam_run_dataset" --dataset "$SEQUENCE" \
  --trajectory "$REPORTS/trajectory.txt" --summary "$REPORTS/summary.json" --threads \
  --backend on --quiet

# Each report is a block from REPORT_MARK to its "=====" line. It is in dslam when a stack of the
# accesses (every paragraph but "Thread T.. created at" and "Location is ..") has a frame that
# names dslam:: or a file of the repository; suppressions matched are printed at exit.
status=0
python3 - "$REPORTS" "$REPORT_MARK" "$REPO" <<'PY' || status=1
import glob, os, re, sys
reports, mark, repo = sys.argv[1], sys.argv[2], sys.argv[3]
in_dslam = other = 0
for path in sorted(glob.glob(os.path.join(reports, "*.[0-9]*"))):
    text = open(path, errors="replace").read()
    for line in re.findall(r"^ThreadSanitizer: Matched.*$|^ *\d+ +\S+:\S+$", text, re.M):
        print("suppression " + os.path.basename(path) + ": " + line.strip())
    for block in re.findall(re.escape(mark) + r".*?\n={10,}", text, re.S):
        paragraphs = re.split(r"\n\s*\n", block)
        accesses = [p for p in paragraphs
                    if not re.match(r"\s*(Thread T\d+|Location is|SUMMARY)", p)]
        ours = any("dslam::" in p or repo in p for p in accesses)
        in_dslam += ours
        other += not ours
        summary = re.search(r"SUMMARY: .*", block)
        print(("IN DSLAM " if ours else "OUTSIDE  ") + os.path.basename(path) + ": " +
              (summary.group(0) if summary else block.splitlines()[0]))
print(f"[sanitize] reports in dslam code: {in_dslam}; elsewhere (listed, not failing): {other}")
sys.exit(1 if in_dslam else 0)
PY
if ((failed_runs > 0)); then
  echo "[sanitize] $failed_runs run(s) failed on their own (see $REPORTS/*.out)"
  status=1
fi
[[ $status -eq 0 ]] && echo "[sanitize] $KIND: OK" || echo "[sanitize] $KIND: FAILED"
exit $status
