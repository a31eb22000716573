// dslam_odometry_node: a stand-alone node that loads the dslam/OdometryNodelet into its own
// process (same topics, parameters and services as the nodelet, with the node's name).
#include <nodelet/loader.h>
#include <ros/ros.h>

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
