#include "dslam/ros/node_config.h"

#include <sstream>

#include "dslam/core/config_markdown.h"

namespace dslam {
namespace ros_layer {

std::string DescribeNodeConfigMarkdown() {
  std::ostringstream out;
  out << MarkdownFieldTableHeader();
  const NodeConfig defaults;
  NodeConfig::Fields(defaults, MarkdownFieldWriter("~", &out));
  return out.str();
}

}  // namespace ros_layer
}  // namespace dslam
