#!/usr/bin/env bash
# Proves a refactor by equality: runs dslam_run_dataset from two builds, synchronously, on the
# benchmark sequences (the synthetic SCENARIOS below x seeds 1-3, 300 frames, rendered once into
# OUT/sequences by the first build's dslam_synth; plus every sequence found in ../shared/data) in
# three modes: the defaults with the back end off, `--backend on`, and `--static-points off`. It
# compares byte for byte the causal (--trajectory) and refined (--refined-trajectory)
# trajectories, the moving objects (--objects), the static map (--map) and, on synthetic
# sequences, the per-frame segmentation (--segmentation); and through
# scripts/dslam_tools/equality.py the status CSV's columns (names, order) and the summary JSON's
# keys (names, order) and every value in them that does not depend on timing. Also renders every
# scenario (40 frames) with both builds' dslam_synth and compares the files.
# Exit 0: all identical. Summary keys of quantiles (median_*, p95_*) are counted apart: with
# DSLAM_EQ_QUANTILES=may-differ they are listed but do not fail the check (a change of the
# quantile rule).
# Usage: scripts/equality_check.sh BEFORE_BIN_DIR AFTER_BIN_DIR [OUT_DIR=build/equality]
# (a BIN_DIR is a workspace's devel/lib/dslam, e.g. of a `git worktree` of the old commit built
# with scripts/setup.sh). Environment: DSLAM_EQ_SCENARIOS, DSLAM_EQ_SEEDS ("1 2 3"),
# DSLAM_EQ_FRAMES (300), DSLAM_EQ_ARGS (extra dslam_run_dataset options for both builds, e.g.
# "--config FILE"), DSLAM_EQ_QUANTILES, DSLAM_EQ_CACHE (the rendered sequences' folder, default
# OUT/sequences; checks of several changes can share one).
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BEFORE=$1; AFTER=$2; OUT="${3:-$REPO/build/equality}"
CACHE="${DSLAM_EQ_CACHE:-$OUT/sequences}"; SHARED="$(dirname "$REPO")/shared/data"
SCENARIOS="${DSLAM_EQ_SCENARIOS:-walking walking_static close_person walking_halfsphere slow_box nonrigid_sheet static_room fast_rotation}"
SEEDS="${DSLAM_EQ_SEEDS:-1 2 3}"; FRAMES="${DSLAM_EQ_FRAMES:-300}"
COMPARE=(python3 "$REPO/scripts/dslam_tools/equality.py")
mkdir -p "$CACHE" "$OUT/before" "$OUT/after"
# Scenarios both builds know (a scenario added by the change has no "before").
known="$("$BEFORE/dslam_synth" --list | awk '{print $1}')"
SCENARIOS="$(for s in $SCENARIOS; do if grep -qx "$s" <<< "$known"; then echo "$s"; fi; done)"
sequences=()
for scenario in $SCENARIOS; do
  for seed in $SEEDS; do
    folder="$CACHE/${scenario}_f${FRAMES}_s${seed}"
    [[ -f "$folder/groundtruth.txt" ]] || "$BEFORE/dslam_synth" --scenario "$scenario" \
      --frames "$FRAMES" --seed "$seed" --output "$folder" > /dev/null
    sequences+=("$folder")
  done
done
for real in "$SHARED"/*/; do
  [[ -f "$real/rgb.txt" ]] && sequences+=("${real%/}")
done

# run SIDE FOLDER MODE NAME: one dslam_run_dataset run of the SIDE's build, outputs OUT/SIDE/NAME.*
run() {
  local side=$1 folder=$2 mode=$3 name=$4 bin=$BEFORE
  [[ $side == after ]] && bin=$AFTER
  local base="$OUT/$side/$name" args=()
  case "$mode" in
    off) args=(--backend off) ;;
    on) args=(--backend on) ;;
    nospd) args=(--static-points off --backend off) ;;
  esac
  [[ -f "$folder/mask.txt" ]] && args+=(--segmentation "$base.segmentation.csv")
  # shellcheck disable=SC2086
  "$bin/dslam_run_dataset" --dataset "$folder" --trajectory "$base.txt" \
    --refined-trajectory "$base.refined.txt" --objects "$base.objects.txt" --map "$base.pcd" \
    --status "$base.status.csv" --summary "$base.summary.json" --quiet "${args[@]}" \
    ${DSLAM_EQ_ARGS:-} > "$base.log" 2>&1
}

status=0; quantile_files=0; compared=0
# verdict NAME: compares the outputs of NAME; prints one line.
verdict() {
  local name=$1 differ=() code=0
  for ext in txt refined.txt objects.txt pcd segmentation.csv; do
    local b="$OUT/before/$name.$ext" a="$OUT/after/$name.$ext"
    [[ -e "$b" || -e "$a" ]] || continue
    cmp -s "$b" "$a" || differ+=("$ext")
  done
  "${COMPARE[@]}" csv "$OUT/before/$name.status.csv" "$OUT/after/$name.status.csv" \
    > "$OUT/$name.status.diff" || differ+=(status.csv)
  "${COMPARE[@]}" json "$OUT/before/$name.summary.json" "$OUT/after/$name.summary.json" \
    > "$OUT/$name.summary.diff" || code=$?
  ((code == 1)) && differ+=(summary.json)
  compared=$((compared + 1))
  if ((code == 3)); then
    quantile_files=$((quantile_files + 1))
    [[ "${DSLAM_EQ_QUANTILES:-}" == may-differ ]] || differ+=("summary.json quantiles")
  fi
  if ((${#differ[@]} == 0)); then
    echo "identical  $name$( ((code == 3)) && echo " (quantile keys differ)")"
  else
    echo "DIFFERENT  $name: ${differ[*]}"
    cat "$OUT/$name.status.diff" "$OUT/$name.summary.diff"
    status=1
  fi
}

for folder in "${sequences[@]}"; do
  for mode in off on nospd; do
    name="$(basename "$folder")_$mode"
    run before "$folder" "$mode" "$name" & pid=$!  # both builds side by side (2 cores)
    run after "$folder" "$mode" "$name" || { echo "FAILED     $name (after)"; status=1; }
    wait "$pid" || { echo "FAILED     $name (before)"; status=1; }
    verdict "$name"
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
echo "equality: $compared runs compared, $quantile_files with quantile keys that differ"
[[ $status -eq 0 ]] && echo "equality: all identical" || echo "equality: DIFFERENCES"
exit $status
