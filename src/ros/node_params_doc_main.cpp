// dslam_node_params_doc: prints the Markdown table of the ROS layer's own parameters (the
// nodelet's ~keys, NodeConfig) for docs/parameters.md (scripts/update_readme.sh). The core
// parameters' table is dslam_config_doc's: tools may not include ROS headers.
#include <iostream>
#include <string>

#include "dslam/ros/node_config.h"

int main(int argc, char** argv) {
  if (argc != 1) {
    std::cerr << "usage: dslam_node_params_doc\n";
    return 2;
  }
  std::cout << dslam::ros_layer::DescribeNodeConfigMarkdown();
  return 0;
}
