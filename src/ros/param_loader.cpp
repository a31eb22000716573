#include "dslam/ros/param_loader.h"

#include <ros/console.h>
#include <ros/node_handle.h>

#include <set>
#include <type_traits>

#include "dslam/core/removed_config_keys.h"

namespace dslam {
namespace ros_layer {
namespace {

using XmlRpc::XmlRpcValue;

/// Visitor that reads each field present in one XmlRpc struct and records the keys it used.
class XmlRpcReader {
 public:
  XmlRpcReader(const XmlRpcValue& tree, std::string prefix, std::set<std::string>* used)
      : tree_(tree), prefix_(std::move(prefix)), used_(used) {}

  template <typename T>
  void operator()(const FieldInfo& info, T& value) const {
    if (!tree_.hasMember(info.name)) return;
    used_->insert(info.name);
    XmlRpcValue field = tree_[info.name];  // a copy: the conversions are non-const
    if (!Read(field, &value)) {
      throw ConfigError(prefix_ + info.name + ": cannot read '" + field.toXml() + "' as " +
                        FieldTypeName<T>());
    }
  }

 private:
  static bool Read(XmlRpcValue& v, bool* out) {
    if (v.getType() != XmlRpcValue::TypeBoolean) return false;
    *out = static_cast<bool>(v);
    return true;
  }
  static bool Read(XmlRpcValue& v, std::string* out) {
    if (v.getType() != XmlRpcValue::TypeString) return false;
    *out = static_cast<std::string>(v);
    return true;
  }
  static bool Read(XmlRpcValue& v, double* out) {
    if (v.getType() == XmlRpcValue::TypeDouble)
      *out = static_cast<double>(v);
    else if (v.getType() == XmlRpcValue::TypeInt)
      *out = static_cast<int>(v);
    else
      return false;
    return true;
  }
  template <typename T>
  static bool Read(XmlRpcValue& v, T* out) {
    static_assert(std::is_integral<T>::value, "unsupported parameter type");
    if (v.getType() != XmlRpcValue::TypeInt) return false;
    *out = static_cast<T>(static_cast<int>(v));
    return true;
  }
  const XmlRpcValue& tree_;
  std::string prefix_;
  std::set<std::string>* used_;
};

/// Keys of an XmlRpc struct that are not in `used`, as an error naming the first. With
/// `section`, a key removed from it (removed_config_keys.h) is no error: its warning is appended
/// to `warnings`.
void RejectUnknown(const XmlRpcValue& tree, const std::set<std::string>& used,
                   const std::string& prefix, const char* what, const char* section = nullptr,
                   std::vector<std::string>* warnings = nullptr) {
  for (auto it = tree.begin(); it != tree.end(); ++it) {
    if (used.count(it->first)) continue;
    const RemovedConfigKey* removed =
        section != nullptr ? FindRemovedConfigKey(section, it->first) : nullptr;
    if (removed == nullptr) throw ConfigError(prefix + it->first + ": " + what);
    warnings->push_back(RemovedConfigKeyWarning(prefix + it->first, *removed));
  }
}

}  // namespace

void LoadParamTree(const XmlRpcValue& tree, const std::string& ns, Config* config, NodeConfig* node,
                   std::vector<std::string>* warnings) {
  const std::string root = ns.empty() || ns.back() == '/' ? ns : ns + "/";
  if (tree.getType() != XmlRpcValue::TypeStruct) {
    throw ConfigError(root + ": parameters must form a namespace (struct)");
  }
  std::set<std::string> used;
  NodeConfig::Fields(*node, XmlRpcReader(tree, root, &used));
  Config::Sections(*config, [&](const char* name, auto& section) {
    if (!tree.hasMember(name)) return;
    used.insert(name);
    const XmlRpcValue& sub = tree[name];
    const std::string prefix = root + name + "/";
    if (sub.getType() != XmlRpcValue::TypeStruct) {
      throw ConfigError(prefix + ": must be a namespace of parameters");
    }
    std::set<std::string> keys;
    using Section = std::decay_t<decltype(section)>;
    Section::Fields(section, XmlRpcReader(sub, prefix, &keys));
    RejectUnknown(sub, keys, prefix, "unknown parameter", name, warnings);
  });
  RejectUnknown(tree, used, root, "unknown parameter or config section");
  NodeConfig::Fields(static_cast<const NodeConfig&>(*node), BoundsChecker(root));
  config->Validate();
}

void LoadRosParams(const ros::NodeHandle& private_nh, Config* config, NodeConfig* node) {
  XmlRpcValue tree;
  if (!private_nh.getParam(private_nh.getNamespace(), tree)) return;  // nothing set
  std::vector<std::string> warnings;
  LoadParamTree(tree, private_nh.getNamespace(), config, node, &warnings);
  for (const std::string& warning : warnings) ROS_WARN("%s", warning.c_str());
}

}  // namespace ros_layer
}  // namespace dslam
