#pragma once
// Reading the Config tree and the ROS layer's NodeConfig from ROS parameters: every core key is
// ~section/key (e.g. ~tracking/window_keyframes), every ROS-layer key is ~key. Driven by the same
// Fields() visitors as the YAML loader, so unknown keys and values of the wrong type are errors
// naming the parameter.

#include <string>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

#include "dslam/core/config.h"
#include "dslam/ros/node_config.h"

namespace ros {
class NodeHandle;
}

namespace dslam {
namespace ros_layer {

/// Overrides `config` and `node` with the values of `tree` (the struct of a private parameter
/// namespace). `ns` prefixes parameter names in error messages. Throws ConfigError naming the
/// parameter on an unknown key, a wrong type or an out-of-range value; validates both. A core key
/// dslam no longer has (removed_config_keys.h) is ignored: a warning naming it (e.g.
/// "/dslam/tracking/descriptor_observations was removed (...); its value is ignored") is appended
/// to `warnings`.
void LoadParamTree(const XmlRpc::XmlRpcValue& tree, const std::string& ns, Config* config,
                   NodeConfig* node, std::vector<std::string>* warnings);

/// LoadParamTree on the parameters under `private_nh`'s namespace (nothing set: defaults); the
/// warnings about removed keys are logged with ROS_WARN.
void LoadRosParams(const ros::NodeHandle& private_nh, Config* config, NodeConfig* node);

}  // namespace ros_layer
}  // namespace dslam
