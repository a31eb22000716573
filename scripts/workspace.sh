# Sourced by scripts/setup.sh, test.sh and sanitize.sh: the environment and the one catkin_make
# call that configure and build a dslam workspace, so that each workspace is configured once and
# never re-configured because two scripts passed different CMake arguments.
#
# Sets REPO (this checkout) and, when not set already, WS (DSLAM_WS, default build/ws), JOBS
# (DSLAM_JOBS, 2), ROS_HOME (build/ros_home) and the compiler cache: CCACHE_DIR (default
# ${XDG_CACHE_HOME:-$HOME/.cache}/dslam/ccache, outside the checkout so that a fresh clone
# compiles from the cache; set CCACHE_DIR to move it), CCACHE_BASEDIR (the repository: paths
# below it are hashed relative to the compiler's directory, so a clone elsewhere hits the same
# entries) and CCACHE_NOHASHDIR (the working directory is not hashed either).
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"  # a non-Debian python3 must not shadow Debian's
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WS="${DSLAM_WS:-$REPO/build/ws}"
JOBS="${DSLAM_JOBS:-2}"
export ROS_HOME="${ROS_HOME:-$REPO/build/ros_home}"
export CCACHE_DIR="${CCACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/dslam/ccache}"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$REPO}"
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"

# The CMake arguments of every workspace; a workspace adds its own (sanitize.sh:
# -DDSLAM_SANITIZE=...) and passes them on every call.
DSLAM_CMAKE_ARGS=(-DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3
                  -DPython3_EXECUTABLE=/usr/bin/python3 -DCATKIN_ENABLE_TESTING=ON)

# dslam_catkin_make [-DVAR=VALUE...] [TARGET...]: catkin_make in $WS with DSLAM_CMAKE_ARGS, the
# given CMake arguments and make targets, -j$JOBS. catkin_make re-runs CMake only when the
# arguments differ from the last call's (build/catkin_make.cache), so every call of one workspace
# must pass the same -D arguments.
dslam_catkin_make() {
  (cd "$WS" && catkin_make "${DSLAM_CMAKE_ARGS[@]}" -j"$JOBS" "$@")
}
