#!/usr/bin/env bash
# Proves a refactor by equality: runs dslam_run_dataset from two builds on every benchmark
# sequence of BENCHMARKS.md (the 8 synthetic scenarios of SCENARIOS below x seeds 1-3, 300
# frames, rendered once into the cache by the first build's dslam_synth; plus ../shared/data when
# present), static points on and off, and compares the trajectories byte for byte. Also renders every scenario (40 frames)
# with both builds' dslam_synth and compares the files. Exit 0: all identical.
# Usage: scripts/equality_check.sh BEFORE_BIN_DIR AFTER_BIN_DIR [OUT_DIR=build/equality]
# (a BIN_DIR is a workspace's devel/lib/dslam, e.g. of a `git worktree` of the old commit built
# with scripts/setup.sh). Extra dslam_run_dataset options: DSLAM_EQ_ARGS="--backend off".
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BEFORE=$1; AFTER=$2; OUT="${3:-$REPO/build/equality}"
CACHE="$OUT/sequences"; SHARED="$(dirname "$REPO")/shared/data"
SCENARIOS="walking walking_static close_person walking_halfsphere slow_box nonrigid_sheet static_room fast_rotation"
mkdir -p "$CACHE" "$OUT/before" "$OUT/after"
# Scenarios both builds know (a scenario added by the change has no "before").
known="$("$BEFORE/dslam_synth" --list | awk '{print $1}')"
SCENARIOS="$(for s in $SCENARIOS; do if grep -qx "$s" <<< "$known"; then echo "$s"; fi; done)"
sequences=()
for scenario in $SCENARIOS; do
  for seed in 1 2 3; do
    folder="$CACHE/${scenario}_f300_s${seed}"
    [[ -f "$folder/groundtruth.txt" ]] || "$BEFORE/dslam_synth" --scenario "$scenario" \
      --frames 300 --seed "$seed" --output "$folder" > /dev/null
    sequences+=("$folder")
  done
done
for real in bonn_crowd_frames300-599 tum_fr1_desk_9frames; do
  [[ -d "$SHARED/$real" ]] && sequences+=("$SHARED/$real")
done
status=0
for folder in "${sequences[@]}"; do
  for static_points in on off; do
    name="$(basename "$folder")_$static_points"
    for side in before after; do
      bin=$BEFORE; [[ $side == after ]] && bin=$AFTER
      # shellcheck disable=SC2086
      "$bin/dslam_run_dataset" --dataset "$folder" --trajectory "$OUT/$side/$name.txt" \
        --static-points "$static_points" --quiet ${DSLAM_EQ_ARGS:-} > /dev/null
    done
    if cmp -s "$OUT/before/$name.txt" "$OUT/after/$name.txt"; then
      echo "identical  $name"
    else
      echo "DIFFERENT  $name"; status=1
    fi
  done
done
# Render comparison: the benchmark scenarios and `loop` (the long-run input, scripts/long_run.py).
RENDERED="$SCENARIOS$(grep -qx loop <<< "$known" && echo " loop" || true)"
for scenario in $RENDERED; do
  for side in before after; do
    bin=$BEFORE; [[ $side == after ]] && bin=$AFTER
    rm -rf "$OUT/render_$side/$scenario"
    "$bin/dslam_synth" --scenario "$scenario" --frames 40 --seed 2 \
      --output "$OUT/render_$side/$scenario" > /dev/null
  done
  if diff -r "$OUT/render_before/$scenario" "$OUT/render_after/$scenario" > /dev/null; then
    echo "identical  render $scenario"
  else
    echo "DIFFERENT  render $scenario"; status=1
  fi
done
[[ $status -eq 0 ]] && echo "equality: all identical" || echo "equality: DIFFERENCES"
exit $status
