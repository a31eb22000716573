#!/usr/bin/env bash
# One-command setup on Debian 12 (run as root, or with sudo available): installs the Debian
# packages dslam needs (skipped when already installed) and builds the catkin workspace
# build/ws (Release, -j2) whose src/dslam links to this repository's files. Idempotent; a re-run with
# nothing changed takes seconds. Prints the workspace path; `source build/ws/devel/setup.bash`.
# Extra arguments go to catkin_make: -DVAR=VALUE (pass the same ones on every call of one
# workspace, scripts/workspace.sh says why) and make targets.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/workspace.sh"

PACKAGES=(
  build-essential cmake git ccache
  ros-core-dev rosbash libnodeletlib-dev libnodeletlib-tools
  libtf2-ros-dev libtf2-eigen-dev libtf2-geometry-msgs-dev libcv-bridge-dev libimage-transport-dev
  libpcl-conversions-dev libpcl-dev libceres-dev libcgal-dev libopencv-dev libeigen3-dev
  libyaml-cpp-dev libgtest-dev libjemalloc-dev liboctomap-dev
  libroscpp-dev libmessage-filters-dev libstd-msgs-dev libstd-srvs-dev libsensor-msgs-dev
  libnav-msgs-dev libgeometry-msgs-dev libvisualization-msgs-dev libtf2-dev pluginlib-dev
  ros-message-generation ros-message-runtime
  python3-rostest python3-rosbag python3-sensor-msgs python3-nav-msgs python3-geometry-msgs
  python3-visualization-msgs python3-std-srvs python3-tf2-msgs python3-tf2-ros python3-cv-bridge
  python3-numpy python3-matplotlib python3-yaml python3-opencv python3-nose
  rviz xvfb xauth x11-utils imagemagick
)

missing=()
for pkg in "${PACKAGES[@]}"; do
  status="$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)"
  [[ "$status" == "install ok installed" ]] || missing+=("$pkg")
done
if ((${#missing[@]})); then
  echo "[setup] installing ${#missing[@]} Debian packages: ${missing[*]}"
  SUDO=""; [[ $(id -u) -eq 0 ]] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
else
  echo "[setup] Debian packages: all ${#PACKAGES[@]} present"
fi

# src/dslam is a folder of links to the repository's top-level entries, all but build/ and out/:
# a link to the whole repository would contain the workspace itself, and rosrun's `find -L`
# would then report a file-system loop.
PKG="$WS/src/dslam"
[[ -L "$PKG" ]] && rm -f "$PKG"
mkdir -p "$PKG"
for entry in "$REPO"/* "$REPO"/.clang-format; do
  name="$(basename "$entry")"
  case "$name" in build|out) continue ;; esac
  [[ "$(readlink "$PKG/$name" 2>/dev/null)" == "$entry" ]] || ln -sfn "$entry" "$PKG/$name"
done
for link in "$PKG"/*; do [[ -e "$link" ]] || rm -f "$link"; done  # entries removed from the repo

echo "[setup] building $WS (Release, -j$JOBS, compiler cache $CCACHE_DIR)"
dslam_catkin_make "$@" > "$WS/build.log" 2>&1 \
  || { tail -n 60 "$WS/build.log"; echo "[setup] build failed: $WS/build.log"; exit 1; }
echo "[setup] ok: source $WS/devel/setup.bash"
