#!/usr/bin/env bash
# Runs every test of dslam (gtest, Python tests, rostest): sets up and builds first (setup.sh),
# then `catkin_make run_tests`, and gates on catkin_test_results (catkin_make run_tests alone exits
# 0 on failures). Results: build/ws/build/test_results/dslam/*.xml. Ends with 'N passed, N failed'.
set -euo pipefail
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WS="${DSLAM_WS:-$REPO/build/ws}"
"$REPO/scripts/setup.sh"

export ROS_HOME="${ROS_HOME:-$REPO/build/ros_home}"
export ROSCONSOLE_STDOUT_LINE_BUFFERED=1 PYTHONUNBUFFERED=1
export CCACHE_DIR="${CCACHE_DIR:-$REPO/build/ccache}"
RESULTS="$WS/build/test_results"
rm -rf "$RESULTS"
cd "$WS"
set +u; source devel/setup.bash; set -u
echo "[test] building and running tests (log: $WS/test.log)"
if ! catkin_make -j"${DSLAM_JOBS:-2}" run_tests > "$WS/test.log" 2>&1; then
  tail -n 80 "$WS/test.log"
  echo "[test] building or running the tests failed: $WS/test.log"
  echo "0 passed, 1 failed"
  exit 1
fi
status=0
catkin_test_results --all "$RESULTS" > "$WS/test_results.txt" 2>&1 || status=$?
if [[ $status -ne 0 ]]; then grep -vE '^(Skipping|$)' "$WS/test_results.txt" || true; fi
python3 - "$RESULTS" <<'PY'
import glob, sys, xml.etree.ElementTree as ET
passed = failed = skipped = 0
for path in glob.glob(sys.argv[1] + "/**/*.xml", recursive=True):
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError:
        failed += 1
        continue
    for case in root.iter("testcase"):
        if case.find("failure") is not None or case.find("error") is not None:
            failed += 1
        elif case.find("skipped") is not None:
            skipped += 1
        else:
            passed += 1
print(f"{passed} passed, {failed} failed" + (f", {skipped} skipped" if skipped else ""))
PY
if [[ $status -ne 0 ]]; then echo "[test] FAILED (see $WS/test.log)"; fi
exit $status
