// dslam_odometry_node: a stand-alone node that loads the dslam/OdometryNodelet into its own
// process (same topics, parameters and services as the nodelet, with the node's name).
#include <nodelet/loader.h>
#include <ros/ros.h>

// jemalloc, this executable's malloc (DSLAM_NODE_ALLOCATOR links it first), reads its options
// from this symbol: a background thread returns freed pages to the system on time, also those of
// threads that allocate rarely (loop closing), instead of only when that thread's arena is used
// again. The minute's heap line in the log says whether it runs.
extern "C" {
// NOLINTNEXTLINE(readability-identifier-naming): the name jemalloc looks up
const char* malloc_conf = "background_thread:true";
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "dslam");
  nodelet::Loader loader;
  const nodelet::M_string remappings = ros::names::getRemappings();
  const nodelet::V_string args(argv + 1, argv + argc);
  if (!loader.load(ros::this_node::getName(), "dslam/OdometryNodelet", remappings, args)) {
    ROS_FATAL("dslam: could not load the dslam/OdometryNodelet plugin");
    return 1;
  }
  ros::spin();
  return 0;
}
