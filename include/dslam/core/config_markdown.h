#pragma once
// The parameter table of docs/parameters.md: a Fields() visitor that writes one Markdown row per
// field (name, default, unit, range, meaning). Used for the core Config (io/config_io.h,
// dslam_config_doc) and the ROS layer's NodeConfig (ros/node_config.h, dslam_node_params_doc).

#include <sstream>
#include <string>
#include <utility>

#include "dslam/core/config_field.h"

namespace dslam {

/// The header of the table MarkdownFieldWriter fills (two lines, each ending in '\n').
inline const char* MarkdownFieldTableHeader() {
  return "| parameter | default | unit | range | meaning |\n|---|---|---|---|---|\n";
}

/// Visitor that appends one Markdown table row per field: `prefix` + name, the value as default,
/// unit, bounds (numbers: [min, max]; strings: the choices; bools: none) and the description.
class MarkdownFieldWriter {
 public:
  MarkdownFieldWriter(std::string prefix, std::ostringstream* out)
      : prefix_(std::move(prefix)), out_(out) {}

  template <typename T>
  void operator()(const FieldInfo& info, const T& value) const {
    *out_ << "| `" << prefix_ << info.name << "` | " << Value(value) << " | " << info.unit << " | "
          << Range(info, value) << " | " << info.doc << " |\n";
  }

 private:
  static std::string Value(bool v) { return v ? "true" : "false"; }
  static std::string Value(const std::string& v) { return v.empty() ? "(empty)" : "`" + v + "`"; }
  template <typename T>
  static std::string Value(const T& v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }
  static std::string Range(const FieldInfo& info, const std::string&) {
    std::string r;
    for (const auto& c : info.choices) r += (r.empty() ? "" : ", ") + c;
    return r;
  }
  static std::string Range(const FieldInfo&, bool) { return ""; }
  template <typename T>
  static std::string Range(const FieldInfo& info, const T&) {
    std::ostringstream s;
    s << "[" << (info.min_value == kNoMin ? std::string("-inf") : Value(info.min_value)) << ", "
      << (info.max_value == kNoMax ? std::string("inf") : Value(info.max_value)) << "]";
    return s.str();
  }
  std::string prefix_;
  std::ostringstream* out_;
};

}  // namespace dslam
