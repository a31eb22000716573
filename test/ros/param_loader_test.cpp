#include "dslam/ros/param_loader.h"

#include <gtest/gtest.h>

namespace dslam {
namespace ros_layer {
namespace {

XmlRpc::XmlRpcValue Tree() {
  XmlRpc::XmlRpcValue tree;
  tree["queue_size"] = 3;
  tree["odom_frame"] = std::string("world_odom");
  tree["tracking"]["window_keyframes"] = 5;
  tree["dataset"]["association_max_dt_s"] = 0;  // an integer is accepted for a number
  return tree;
}

TEST(ParamLoader, ReadsNodeAndCoreKeys) {
  Config config;
  NodeConfig node;
  LoadParamTree(Tree(), "/dslam", &config, &node);
  EXPECT_EQ(node.queue_size, 3);
  EXPECT_EQ(node.odom_frame, "world_odom");
  EXPECT_EQ(config.tracking.window_keyframes, 5);
  EXPECT_DOUBLE_EQ(config.dataset.association_max_dt_s, 0.0);
}

void ExpectError(const XmlRpc::XmlRpcValue& tree, const std::string& name) {
  Config config;
  NodeConfig node;
  try {
    LoadParamTree(tree, "/dslam", &config, &node);
    FAIL() << "no error for " << name;
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
  }
}

TEST(ParamLoader, ErrorsNameTheParameter) {
  XmlRpc::XmlRpcValue unknown = Tree();
  unknown["tracking"]["no_such_key"] = 1;
  ExpectError(unknown, "/dslam/tracking/no_such_key");
  XmlRpc::XmlRpcValue wrong_type = Tree();
  wrong_type["publish_tf"] = std::string("yes");
  ExpectError(wrong_type, "/dslam/publish_tf");
  XmlRpc::XmlRpcValue out_of_range = Tree();
  out_of_range["queue_size"] = 0;
  ExpectError(out_of_range, "queue_size");
  XmlRpc::XmlRpcValue unknown_top = Tree();
  unknown_top["qeue_size"] = 3;
  ExpectError(unknown_top, "/dslam/qeue_size");
}

}  // namespace
}  // namespace ros_layer
}  // namespace dslam
