#!/usr/bin/env bash
# The README's main command: runs dslam as users do. Sets up and builds (scripts/setup.sh),
# generates the default synthetic scenario (walking, 150 frames, seed 1) as a TUM folder and a
# bag, runs `roslaunch dslam tum_bag.launch` on the bag (headless), evaluates the saved trajectory
# with dslam_eval and plots it, then prints where everything went. Output: out/demo/.
set -euo pipefail
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WS="${DSLAM_WS:-$REPO/build/ws}"
OUT="${DSLAM_DEMO_OUT:-$REPO/out/demo}"
SCENARIO="${DSLAM_DEMO_SCENARIO:-walking}"
FRAMES="${DSLAM_DEMO_FRAMES:-150}"
RATE="${DSLAM_DEMO_RATE:-1.0}"

"$REPO/scripts/setup.sh"
export ROS_HOME="${ROS_HOME:-$REPO/build/ros_home}"
export ROSCONSOLE_STDOUT_LINE_BUFFERED=1 PYTHONUNBUFFERED=1
set +u; source "$WS/devel/setup.bash"; set -u
mkdir -p "$OUT"
cd "$OUT"

echo "[demo] generating the synthetic '$SCENARIO' scenario ($FRAMES frames, seed 1) and its bag"
rosrun dslam dslam_synth --scenario "$SCENARIO" --frames "$FRAMES" --seed 1 \
  --output "$OUT/$SCENARIO" --bag "$OUT/$SCENARIO.bag" --preview "$OUT/preview.png" > synth.log 2>&1 \
  || { tail -n 20 synth.log; exit 1; }

echo "[demo] roslaunch dslam tum_bag.launch bag:=$OUT/$SCENARIO.bag rate:=$RATE rviz:=false"
roslaunch dslam tum_bag.launch bag:="$OUT/$SCENARIO.bag" trajectory:="$OUT/trajectory.txt" \
  camera:="$OUT/$SCENARIO/camera.yaml" rviz:=false rate:="$RATE" summary:="$OUT/node.json" \
  > roslaunch.log 2>&1 || { tail -n 40 roslaunch.log; exit 1; }
grep '^bag_runner:' roslaunch.log | sed 's/^/[demo] /'

echo "[demo] evaluating against the ground truth"
rosrun dslam dslam_eval --groundtruth "$OUT/$SCENARIO/groundtruth.txt" \
  --trajectory "$OUT/trajectory.txt" --json "$OUT/eval.json" | tee eval.txt
rosrun dslam plot_trajectory --groundtruth "$OUT/$SCENARIO/groundtruth.txt" \
  --trajectory "$OUT/trajectory.txt" --output "$OUT/trajectory.png" > plot.log 2>&1 || { cat plot.log; exit 1; }

cat <<EOT
[demo] done. Outputs in $OUT:
  $SCENARIO/  synthetic TUM-layout folder (rgb/, depth/, mask/, groundtruth.txt)
  $SCENARIO.bag  the same frames as a rosbag (TUM topics)
  preview.png           a frame of the scenario with its dynamic mask
  trajectory.txt        every tracked pose from the ROS node (TUM format, camera optical frame)
  node.json             frames received / processed / dropped, latency, per-frame time
  eval.txt, eval.json   ATE / RPE / coverage from dslam_eval
  trajectory.png        estimate vs ground truth (plot_trajectory)
  roslaunch.log         the node's log
EOT
