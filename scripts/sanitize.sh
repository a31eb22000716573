#!/usr/bin/env bash
# Builds dslam with a sanitizer in a workspace of its own and runs that sanitizer's checks; exit 0
# when it reported nothing in dslam code. Not part of scripts/test.sh: it is a second,
# instrumented build of dslam, and the runs are several times slower.
#
# Usage: scripts/sanitize.sh KIND
#   thread   ThreadSanitizer, workspace build/tsan: test_slam_threads (the back-end thread against
#            the synchronous mode, Reset and destruction with work queued, keyframe observers, a
#            dynamic scene whose map changes while a run is in flight), test_static_map_slam (the
#            static map fused on the back-end thread while another thread reads it),
#            test_loop_closing_threads (loop detection and keyframe corrections from the
#            back-end thread beside tracking), then
#            `dslam_run_dataset --threads --backend on --map --map-unmasked --objects` (the
#            objects' mask and optical flow side by side on OpenCV's pool) on
#            $DSLAM_SANITIZE_FRAMES (80) frames of the synthetic `walking` scenario, seed 1.
#            DSLAM_SANITIZE_SCOPE=ci (scripts/test.sh, so CI): the three gtests only, without
#            their purely synchronous tests, and only their targets built (incremental through
#            the compiler cache).
#   address  AddressSanitizer + LeakSanitizer + UndefinedBehaviorSanitizer (undefined behaviour
#            aborts like a memory error), workspace build/asan: every gtest binary of dslam (each
#            `dslam_test(...)` in test/*/CMakeLists.txt: the ROS-free parts and the ros part;
#            not the rostests, not the Python tests), one after the other.
# Examples: scripts/sanitize.sh address        # full build + all gtests
#           DSLAM_SANITIZE_TESTS="test_core test_io" scripts/sanitize.sh address   # a subset
#
# Every dslam library, tool and gtest gets the kind's -fsanitize flags, -g -O1 (DSLAM_SANITIZE in
# cmake/dslam_parts.cmake); the Debian libraries stay uninstrumented, and scripts/<kind>.supp
# files suppress reports that lie entirely in them (each line justified there). Reports go to
# build/<ws>/reports/; a report with a frame in dslam (a `dslam::` function or a file of this
# repository) fails the run, any other report is listed. A run also fails when its program
# exits non-zero (a failing test) or, for gtest binaries, stops before gtest's final summary.
# Environment: DSLAM_JOBS (2), DSLAM_SANITIZE_FRAMES (80), DSLAM_SANITIZE_TESTS (address: the
# gtest binaries to build and run, default all), DSLAM_SANITIZE_SCOPE (full, or ci: above).
# Besides the gtests' own XML files, $REPORTS/sanitizer_verdict.xml holds one JUnit test case,
# failed when a report lies in dslam code or a run failed (scripts/test.sh counts both).
set -euo pipefail
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
KIND="${1:-}"
FRAMES="${DSLAM_SANITIZE_FRAMES:-80}"
SCOPE="${DSLAM_SANITIZE_SCOPE:-full}"
START_S=$SECONDS

# Per kind: the workspace name and the start of a report's first line.
kind_settings() {
  case "$KIND" in
    thread)
      NAME=tsan REPORT_MARK="WARNING: ThreadSanitizer:" ;;
    address)
      NAME=asan REPORT_MARK="ERROR: (Address|Leak)Sanitizer:|runtime error:" ;;
    *)
      echo "usage: scripts/sanitize.sh thread|address" >&2
      exit 2 ;;
  esac
}
kind_settings
WS="$REPO/build/$NAME"
REPORTS="$WS/reports"
BIN="$WS/devel/lib/dslam"

# Every gtest target of dslam: the names declared with dslam_test() in test/*/CMakeLists.txt.
all_gtests() {
  sed -n 's/^dslam_test(\([A-Za-z0-9_]*\).*/\1/p' "$REPO"/test/*/CMakeLists.txt | sort
}

THREAD_GTESTS=(test_slam_threads test_static_map_slam test_loop_closing_threads test_map_session)
case "$KIND" in
  thread)
    TARGETS=("${THREAD_GTESTS[@]}")
    [[ "$SCOPE" == ci ]] || TARGETS+=(dslam_run_dataset_main dslam_synth_main) ;;
  address)
    read -r -a GTESTS <<< "${DSLAM_SANITIZE_TESTS:-$(all_gtests | tr '\n' ' ')}"
    TARGETS=("${GTESTS[@]}") ;;
esac
echo "[sanitize] building $WS with DSLAM_SANITIZE=$KIND (log: $WS/build.log)"
DSLAM_WS="$WS" "$REPO/scripts/setup.sh" -DDSLAM_SANITIZE="$KIND" "${TARGETS[@]}" > /dev/null
BUILD_S=$((SECONDS - START_S))
echo "[sanitize] build: ${BUILD_S} s"
rm -rf "$REPORTS"
mkdir -p "$REPORTS"

# Runtime options. log_path: each process writes its reports to $REPORTS/<run>.<pid>.
#  thread: halt_on_error=0: every report of a run is written; exitcode=0: the exit status is the
#    program's own (a failing test), the reports are judged below.
#  address: ASan and UBSan stop at the first error (UB checks are built without recovery), and
#    exitcode=0 keeps that apart from a failing test: the report is judged below, the missing
#    gtest summary fails the run. UBSan ends the program with status 1 whatever exitcode says,
#    and writes to stderr (kept in $REPORTS/<run>.out, judged too). LeakSanitizer runs at exit
#    and reports every leak.
#    detect_stack_use_after_return: also catches a pointer to a returned function's locals.
sanitizer_env() {
  local name=$1 log="log_path=$REPORTS/$1"
  case "$KIND" in
    thread)
      echo "TSAN_OPTIONS=suppressions=$REPO/scripts/tsan.supp print_suppressions=1 halt_on_error=0"\
           "exitcode=0 second_deadlock_stack=1 $log" ;;
    address)
      echo "ASAN_OPTIONS=exitcode=0 detect_stack_use_after_return=1 strict_string_checks=1"\
           "check_initialization_order=1 detect_leaks=1 $log"
      echo "LSAN_OPTIONS=suppressions=$REPO/scripts/lsan.supp print_suppressions=1"
      echo "UBSAN_OPTIONS=print_stacktrace=1 report_error_type=1" ;;
  esac
}

# taskset (thread only): one CPU. Debian's OpenCV runs cv::parallel_for_ (dslam's ORB extraction
# in features.cpp, the renderer in synth/) on TBB worker threads, and TBB is not instrumented:
# TSan sees neither the hand-over of a loop to the workers nor the join before
# cv::parallel_for_ returns, and reports the loop's data (measured on 45 frames of static_room
# with `dslam_run_dataset --threads --backend on`: 148 such reports, each with a thread created
# in libtbb.so.12, and 5.4 s/frame against 0.17 s). A suppression cannot express "a thread
# created by TBB" (GCC 12's TSan matches suppressions against the access stacks, whose TBB frames
# it cannot record). With one CPU, TBB starts no worker thread and the loops run on the calling
# thread; dslam's own threads (tracking, Slam's back end) stay separate threads, and TSan judges
# them by happens-before, not by simultaneous execution.
CPU="$(python3 -c 'import os; print(min(os.sched_getaffinity(0)))')"
failed_runs=0
run_sanitized() {
  local name=$1 code=0 start=$SECONDS
  shift
  local -a envs pin=()
  mapfile -t envs < <(sanitizer_env "$name")
  [[ "$KIND" == thread ]] && pin=(taskset -c "$CPU")
  echo "[sanitize] $name: $*"
  env "${envs[@]}" "${pin[@]}" "$@" > "$REPORTS/$name.out" 2>&1 || code=$?
  echo "[sanitize] $name: exit status $code, $((SECONDS - start)) s, last line:" \
       "$(tail -n 1 "$REPORTS/$name.out")"
  if ((code != 0)); then failed_runs=$((failed_runs + 1)); fi
}
# A gtest binary (extra arguments go to it); it fails when gtest did not reach its final "[  PASSED  ]" line (stopped by a
# sanitizer report) even with exit status 0.
run_gtest() {
  run_sanitized "$1" "$BIN/$1" --gtest_output="xml:$REPORTS/$1.xml" "${@:2}"
  if ! grep -q '^\[  PASSED  \]' "$REPORTS/$1.out"; then
    echo "[sanitize] $1: stopped before gtest's summary"
    failed_runs=$((failed_runs + 1))
  fi
}

case "$KIND" in
  thread)
    # ci: the tests with a thread beside the caller's (the purely synchronous ones run in the
    # normal build); the synthetic scenes come from DSLAM_TEST_SCENES when scripts/test.sh's
    # normal tests rendered them (test/support/rendered_sequence.h).
    filter=()
    [[ "$SCOPE" == ci ]] && filter=(--gtest_filter="-KeyFrameObserver.ReceivesEveryKeyFrameWithSharedImagesAndLabels:KeyFrameObserver.LabelsArriveWhenTheCallerAsksForNoPoints:SlamThreads.SynchronousModeReportsEachRunWithItsKeyFrame")
    for test in "${THREAD_GTESTS[@]}"; do run_gtest "$test" "${filter[@]}"; done
    if [[ "$SCOPE" != ci ]]; then
      SEQUENCE="$WS/sequences/walking_f${FRAMES}_s1"
      [[ -f "$SEQUENCE/groundtruth.txt" ]] || run_sanitized synth "$BIN/dslam_synth" \
        --scenario walking --frames "$FRAMES" --seed 1 --output "$SEQUENCE"
      run_sanitized run_dataset "$BIN/dslam_run_dataset" --dataset "$SEQUENCE" \
        --trajectory "$REPORTS/trajectory.txt" --summary "$REPORTS/summary.json" --threads \
        --backend on --map "$REPORTS/map.pcd" --map-unmasked "$REPORTS/map_unmasked.pcd" \
        --objects "$REPORTS/objects.txt" --quiet
    fi ;;
  address)
    export ROS_HOME="${ROS_HOME:-$REPO/build/ros_home}"
    for test in "${GTESTS[@]}"; do run_gtest "$test"; done ;;
esac

status=0
python3 "$REPO/scripts/sanitizer_reports.py" "$REPORTS" "$REPORT_MARK" "$REPO" || status=1
if ((failed_runs > 0)); then
  echo "[sanitize] $failed_runs run(s) failed on their own (see $REPORTS/*.out)"
  status=1
fi
echo "[sanitize] wall time: build ${BUILD_S} s, total $((SECONDS - START_S)) s"
python3 - "$REPORTS/sanitizer_verdict.xml" "$KIND" "$status" <<'PY'
import sys
from xml.sax.saxutils import quoteattr
path, kind, status = sys.argv[1], sys.argv[2], int(sys.argv[3])
failure = "" if status == 0 else (
    '<failure message="a report in dslam code or a failed run (see the [sanitize] lines)"/>')
with open(path, "w") as f:
    f.write('<?xml version="1.0"?>\n<testsuite name="sanitize" tests="1" failures="%d">'
            '<testcase classname="sanitize" name=%s>%s</testcase></testsuite>\n'
            % (status != 0, quoteattr(kind + "_no_report_in_dslam_code"), failure))
PY
[[ $status -eq 0 ]] && echo "[sanitize] $KIND: OK" || echo "[sanitize] $KIND: FAILED"
exit $status
