#include "dslam/ros/param_loader.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace dslam {
namespace ros_layer {
namespace {

XmlRpc::XmlRpcValue Tree() {
  XmlRpc::XmlRpcValue tree;
  tree["queue_size"] = 3;
  tree["odom_frame"] = std::string("world_odom");
  tree["publish_map_tf"] = false;
  tree["tracking"]["window_keyframes"] = 5;
  tree["dataset"]["association_max_dt_s"] = 0;  // an integer is accepted for a number
  return tree;
}

TEST(ParamLoader, ReadsNodeAndCoreKeys) {
  Config config;
  NodeConfig node;
  std::vector<std::string> warnings;
  LoadParamTree(Tree(), "/dslam", &config, &node, &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(node.queue_size, 3);
  EXPECT_EQ(node.odom_frame, "world_odom");
  EXPECT_FALSE(node.publish_map_tf);
  EXPECT_EQ(WorldDataFrameId(node), "world_odom");  // no map frame of ours in TF
  EXPECT_EQ(config.tracking.window_keyframes, 5);
  EXPECT_DOUBLE_EQ(config.dataset.association_max_dt_s, 0.0);
}

void ExpectError(const XmlRpc::XmlRpcValue& tree, const std::string& name) {
  Config config;
  NodeConfig node;
  std::vector<std::string> warnings;
  try {
    LoadParamTree(tree, "/dslam", &config, &node, &warnings);
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

// A removed core key is ignored with a warning naming it; unknown keys stay errors.
TEST(ParamLoader, WarnsAboutRemovedKeys) {
  XmlRpc::XmlRpcValue tree = Tree();
  tree["pose"]["solver"] = std::string("ceres");
  tree["backend"]["ba_chi2"] = 9.0;
  Config config;
  NodeConfig node;
  std::vector<std::string> warnings;
  LoadParamTree(tree, "/dslam", &config, &node, &warnings);
  EXPECT_EQ(config.tracking.window_keyframes, 5);
  EXPECT_DOUBLE_EQ(config.pose.chi2_depth, Config().pose.chi2_depth);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].rfind("/dslam/pose/solver was removed (", 0), 0u) << warnings[0];
  EXPECT_EQ(warnings[1],
            "/dslam/backend/ba_chi2 was removed (merged into pose.chi2_depth); its value is "
            "ignored");
  XmlRpc::XmlRpcValue top = Tree();
  top["solver"] = std::string("ceres");  // a removed key outside its section is unknown
  ExpectError(top, "/dslam/solver");
}

}  // namespace
}  // namespace ros_layer
}  // namespace dslam
