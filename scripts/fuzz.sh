#!/usr/bin/env bash
# Builds dslam's libFuzzer targets (test/fuzz/, one harness per file) with clang++
# -fsanitize=fuzzer,address,undefined in build/fuzz and runs each for a number of executions,
# one target after the other (one job each). Not part of scripts/test.sh; the normal build
# replays the stored inputs through the same harnesses (test_io, test_ros, test_map_file:
# FuzzReplay.*).
#
# Usage: scripts/fuzz.sh [TARGET...]          # default: every target
#   targets: camera_yaml config_yaml tum_dataset trajectory depth_conversion ros_conversions
#            keyframe_map
# Environment:
#   DSLAM_FUZZ_RUNS     executions per target (2000000)
#   DSLAM_FUZZ_MAX_LEN  largest input [bytes] (4096)
#   DSLAM_FUZZ_TIMEOUT  seconds one input may take before libFuzzer reports a hang (10)
#   DSLAM_FUZZ_MAX_TIME seconds per target after which it stops even before DSLAM_FUZZ_RUNS
#                       (0: no limit); the summary gives the executions it reached
#   DSLAM_FUZZ_BUILD    build folder (build/fuzz)
# One allocation above 512 MB is a failure (-malloc_limit_mb): no input of MAX_LEN bytes may make
# dslam allocate that much (image sizes are bounded by dslam/core/image_limits.h).
# Inputs: test/fuzz/corpus/<target>/ (seeds, kept in the repository) and
# test/fuzz/regressions/<target>/ (inputs that once failed, replayed first); new coverage goes to
# build/fuzz/corpus/<target>/. A failure leaves its input in build/fuzz/artifacts/<target>/ and
# the log in build/fuzz/logs/<target>.log; the summary lists executions, exec/s, coverage, and
# failures per target. Exit status 1 when a target failed.
set -euo pipefail
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${DSLAM_FUZZ_BUILD:-$REPO/build/fuzz}"
RUNS="${DSLAM_FUZZ_RUNS:-2000000}"
MAX_LEN="${DSLAM_FUZZ_MAX_LEN:-4096}"
TIMEOUT="${DSLAM_FUZZ_TIMEOUT:-10}"
MAX_TIME="${DSLAM_FUZZ_MAX_TIME:-0}"
FUZZ_SRC="$REPO/test/fuzz"
# The TUM-folder and depth-PNG harnesses write their input files to $TMPDIR for every input: in
# memory (/dev/shm) when it is there.
[[ -z "${TMPDIR:-}" && -w /dev/shm ]] && export TMPDIR=/dev/shm

# clang 14 and its runtime libraries (libclang-rt-14-dev holds libFuzzer and the sanitizers).
missing=()
for pkg in clang-14 libclang-rt-14-dev; do
  [[ "$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)" == "install ok installed" ]] ||
    missing+=("$pkg")
done
if ((${#missing[@]})); then
  SUDO=""; [[ $(id -u) -eq 0 ]] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" > /dev/null
fi

if (($# > 0)); then
  TARGETS=("$@")
else
  mapfile -t TARGETS < <(cd "$FUZZ_SRC" && ls -- *_fuzz.cpp | sed 's/_fuzz\.cpp$//')
fi

mkdir -p "$BUILD/logs"
echo "[fuzz] building $BUILD (log: $BUILD/build.log)"
start=$SECONDS
{
  cmake -S "$FUZZ_SRC" -B "$BUILD" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=
  cmake --build "$BUILD" -j"${DSLAM_JOBS:-2}" --target "${TARGETS[@]/#/fuzz_}"
} > "$BUILD/build.log" 2>&1 || { tail -n 40 "$BUILD/build.log"; echo "[fuzz] build failed"; exit 1; }
echo "[fuzz] build: $((SECONDS - start)) s"

failed=0
SUMMARY="$BUILD/summary.md"
echo "| target | executions | exec/s | coverage (cov / ft) | corpus | failures | time |" > "$SUMMARY"
echo "|---|---|---|---|---|---|---|" >> "$SUMMARY"
for target in "${TARGETS[@]}"; do
  corpus="$BUILD/corpus/$target" artifacts="$BUILD/artifacts/$target/"
  log="$BUILD/logs/$target.log"
  mkdir -p "$corpus" "$artifacts" "$FUZZ_SRC/corpus/$target" "$FUZZ_SRC/regressions/$target"
  echo "[fuzz] $target: $RUNS executions (log: $log)"
  start=$SECONDS code=0
  touch "$artifacts/.run_start"  # failures of this run: the artifacts newer than this mark
  # One process fuzzing in the foreground (no -jobs: libFuzzer would fork a child that logs to
  # fuzz-<n>.log in the current folder). detect_leaks: LeakSanitizer after each input that
  # allocated more than it freed.
  ASAN_OPTIONS="detect_leaks=1" UBSAN_OPTIONS="print_stacktrace=1" \
    "$BUILD/fuzz_$target" -runs="$RUNS" -max_total_time="$MAX_TIME" -max_len="$MAX_LEN" -timeout="$TIMEOUT" \
    -malloc_limit_mb=512 -print_final_stats=1 -artifact_prefix="$artifacts" "$corpus" \
    "$FUZZ_SRC/regressions/$target" "$FUZZ_SRC/corpus/$target" > "$log" 2>&1 || code=$?
  seconds=$((SECONDS - start))
  executions="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)"
  rate="$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)"
  coverage="$(grep -oE 'cov: [0-9]+ ft: [0-9]+' "$log" | tail -n 1 | sed 's/cov: //; s/ ft: / \/ /')"
  units="$(find "$corpus" -type f | wc -l)"
  crashes="$(find "$artifacts" -type f -newer "$artifacts/.run_start" | wc -l)"
  if ((code != 0 || crashes > 0)); then
    failed=$((failed + 1))
    grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error|terminate called|  what\(\))' "$log" |
      head -n 5 || true
  fi
  echo "[fuzz] $target: exit $code, ${executions:-?} executions, ${rate:-?} exec/s," \
       "cov/ft ${coverage:-?}, $crashes failure input(s), ${seconds} s"
  echo "| $target | ${executions:-?} | ${rate:-?} | ${coverage:-?} | $units | $crashes | ${seconds} s |" \
    >> "$SUMMARY"
done
cat "$SUMMARY"
((failed == 0)) && echo "[fuzz] OK" || echo "[fuzz] $failed target(s) FAILED (inputs: $BUILD/artifacts/)"
exit $((failed > 0))
