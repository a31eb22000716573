# ROS 1 on a machine whose host name does not resolve (fresh containers): roscore and every node
# advertise themselves by the host name, so nothing can connect and roscore fails to start. When
# neither ROS_HOSTNAME nor ROS_IP is set and the host name does not resolve, this sets
# ROS_HOSTNAME=localhost (enough for everything on one machine) and says so on stderr.
#
# A catkin environment hook (CMakeLists.txt: catkin_add_env_hooks), so `source
# devel/setup.bash` runs it; the scripts that start ROS (scripts/demo.sh, scripts/test.sh,
# scripts/long_run.py) get it through that. POSIX sh: setup.sh and setup.bash both source it.
# DSLAM_HOSTNAME_CHECK names the command that prints the host name (default `hostname`; tests
# replace it).
if [ -z "${ROS_HOSTNAME:-}" ] && [ -z "${ROS_IP:-}" ]; then
  _dslam_host="$(${DSLAM_HOSTNAME_CHECK:-hostname} 2>/dev/null)"
  if [ -z "$_dslam_host" ] || ! getent hosts "$_dslam_host" >/dev/null 2>&1; then
    export ROS_HOSTNAME=localhost
    echo "dslam: host name '$_dslam_host' does not resolve: ROS_HOSTNAME=localhost" >&2
  fi
  unset _dslam_host
fi
