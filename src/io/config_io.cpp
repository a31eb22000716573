#include "dslam/io/config_io.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <iostream>
#include <set>
#include <sstream>
#include <type_traits>

#include "dslam/core/config_markdown.h"
#include "dslam/core/removed_config_keys.h"

namespace dslam {
namespace {

/// Visitor that reads each field of one section from a YAML map and records the keys it used.
class YamlReader {
 public:
  YamlReader(const YAML::Node& node, std::string prefix, std::set<std::string>* used)
      : node_(node), prefix_(std::move(prefix)), used_(used) {}

  template <typename T>
  void operator()(const FieldInfo& info, T& value) const {
    const YAML::Node field = node_[info.name];
    if (!field) return;
    used_->insert(info.name);
    try {
      value = field.as<T>();
    } catch (const YAML::Exception&) {
      throw ConfigError(prefix_ + info.name + ": cannot read '" + YAML::Dump(field) + "' as " +
                        FieldTypeName<T>());
    }
  }

 private:
  const YAML::Node& node_;
  std::string prefix_;
  std::set<std::string>* used_;
};

/// Visitor that appends one `key: value  # [unit] doc` line per field.
class YamlWriter {
 public:
  explicit YamlWriter(std::ostringstream* out) : out_(out) {}

  template <typename T>
  void operator()(const FieldInfo& info, const T& value) const {
    std::ostringstream line;
    line << "  " << info.name << ": " << Value(value);
    std::string text = line.str();
    text.resize(std::max<size_t>(text.size() + 1, 36), ' ');
    *out_ << text << "# [" << info.unit << "] " << info.doc << "\n";
  }

 private:
  static std::string Value(bool v) { return v ? "true" : "false"; }
  static std::string Value(const std::string& v) { return v; }
  /// The shortest text that reads back as `v` (0.6, not yaml-cpp's 0.59999999999999998).
  static std::string Value(double v) {
    char text[32];
    const std::to_chars_result end = std::to_chars(text, text + sizeof(text), v);
    return std::string(text, end.ptr);
  }
  template <typename T>
  static std::string Value(const T& v) {
    YAML::Emitter emitter;
    emitter << v;
    return emitter.c_str();
  }
  std::ostringstream* out_;
};

/// `text` for an error message: control characters as \xNN (a NUL would end what()), cut to
/// 80 characters.
std::string Printable(const std::string& text) {
  std::string out;
  for (const char c : text.substr(0, 80)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) {
      out += c;
    } else {
      static const char kHex[] = "0123456789abcdef";
      out += std::string("\\x") + kHex[byte >> 4] + kHex[byte & 15];
    }
  }
  return text.size() > 80 ? out + "..." : out;
}

/// The text of a map key; a key that is not a scalar ("? [a]: 1", "? {a: 1}: 1") cannot name a
/// section or parameter. `where` is the dotted path of the map ("" for the top level).
std::string KeyName(const YAML::Node& key, const std::string& where) {
  if (!key.IsScalar()) {
    throw ConfigError((where.empty() ? std::string("config") : where) +
                      ": keys must be plain names, got a " +
                      (key.IsMap()        ? "map"
                       : key.IsSequence() ? "sequence"
                                          : "null") +
                      " as a key");
  }
  return key.Scalar();
}

/// `text` appended to `warnings`, or printed to stderr when there is no list.
void Warn(const std::string& text, std::vector<std::string>* warnings) {
  if (warnings != nullptr) {
    warnings->push_back(text);
  } else {
    std::cerr << "dslam: warning: " << text << "\n";
  }
}

void LoadConfigNode(const YAML::Node& root, Config* config, std::vector<std::string>* warnings) {
  if (!root || root.IsNull()) return;
  if (!root.IsMap()) throw ConfigError("config: top level must be a map of sections");
  std::set<std::string> sections;
  Config::Sections(*config, [&](const char* name, auto& section) {
    const YAML::Node node = root[name];
    if (!node) return;
    sections.insert(name);
    if (!node.IsMap()) throw ConfigError(std::string(name) + ": must be a map of parameters");
    std::set<std::string> used;
    using Section = std::decay_t<decltype(section)>;
    Section::Fields(section, YamlReader(node, std::string(name) + ".", &used));
    for (const auto& kv : node) {
      const std::string key = KeyName(kv.first, name);
      if (used.count(key)) continue;
      if (const RemovedConfigKey* removed = FindRemovedConfigKey(name, key)) {
        Warn(RemovedConfigKeyWarning(std::string(name) + "." + key, *removed), warnings);
        continue;
      }
      throw ConfigError(std::string(name) + "." + Printable(key) + ": unknown parameter");
    }
  });
  for (const auto& kv : root) {
    const std::string key = KeyName(kv.first, "");
    if (!sections.count(key)) throw ConfigError(Printable(key) + ": unknown config section");
  }
  config->Validate();
}

}  // namespace

void LoadConfigYaml(const std::string& path, Config* config, std::vector<std::string>* warnings) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ConfigError("config file " + path + ": " + e.what());
  }
  LoadConfigNode(root, config, warnings);
}

void LoadConfigYamlString(const std::string& yaml_text, Config* config,
                          std::vector<std::string>* warnings) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(std::string("config text: ") + e.what());
  }
  LoadConfigNode(root, config, warnings);
}

std::string DescribeConfigYaml(const Config& config) {
  std::ostringstream out;
  out << "# dslam parameters: every section and key with its default value, unit and meaning.\n"
         "# Generated by `rosrun dslam dslam_config_doc --yaml`; a test keeps it in step with the\n"
         "# code. Copy the keys you change into your own file and pass it with --config or as\n"
         "# the ROS parameter namespace.\n";
  Config::Sections(config, [&](const char* name, const auto& section) {
    using Section = std::decay_t<decltype(section)>;
    out << name << ":\n";
    Section::Fields(section, YamlWriter(&out));
  });
  return out.str();
}

std::string DescribeConfigMarkdown(const Config& defaults) {
  std::ostringstream out;
  out << MarkdownFieldTableHeader();
  Config::Sections(defaults, [&](const char* name, const auto& section) {
    using Section = std::decay_t<decltype(section)>;
    Section::Fields(section, MarkdownFieldWriter(std::string(name) + ".", &out));
  });
  return out.str();
}

}  // namespace dslam
