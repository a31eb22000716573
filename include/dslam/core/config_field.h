#pragma once
// Field visitors for the Config tree: one description of every parameter (name, unit, bounds,
// documentation) drives validation, YAML/rosparam loading and the parameter tables of docs/parameters.md.

#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace dslam {

/// Thrown by Validate() and the loaders; the message always names the parameter (dotted path).
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Static description of one parameter, passed to visitors beside a reference to its value.
struct FieldInfo {
  const char* name;                  ///< key inside its section, e.g. "max_dt_s"
  const char* unit;                  ///< unit of the value ("m", "s", "px", "-" for dimensionless)
  double min_value;                  ///< inclusive lower bound (numeric fields)
  double max_value;                  ///< inclusive upper bound (numeric fields)
  const char* doc;                   ///< one-line description
  std::vector<std::string> choices;  ///< allowed values for string fields (empty: any)
};

/// Description of a numeric field: `unit` of the value ("-" for dimensionless), inclusive bounds
/// [min_value, max_value] in that unit, one-line `doc`.
inline FieldInfo Field(const char* name, const char* unit, double min_value, double max_value,
                       const char* doc) {
  return FieldInfo{name, unit, min_value, max_value, doc, {}};
}

/// Description of a bool field (unit "-", bounds [0, 1]).
inline FieldInfo Flag(const char* name, const char* doc) {
  return FieldInfo{name, "-", 0, 1, doc, {}};
}

/// Description of a string field whose value must be one of `choices` (unit "-", bounds 0).
inline FieldInfo Choice(const char* name, std::vector<std::string> choices, const char* doc) {
  return FieldInfo{name, "-", 0, 0, doc, std::move(choices)};
}

/// Name of a field's value type in error messages ("bool", "integer", "number", "string").
template <typename T>
const char* FieldTypeName() {
  if (std::is_same<T, bool>::value) return "bool";
  if (std::is_integral<T>::value) return "integer";
  if (std::is_floating_point<T>::value) return "number";
  return "string";
}

/// Bounds helpers for FieldInfo.
constexpr double kNoMin = -std::numeric_limits<double>::infinity();
constexpr double kNoMax = std::numeric_limits<double>::infinity();

/// Visitor that checks each numeric field against its bounds and each string against its
/// choices. `prefix` is the dotted path of the section being visited ("" for the root).
class BoundsChecker {
 public:
  explicit BoundsChecker(std::string prefix) : prefix_(std::move(prefix)) {}

  template <typename T>
  void operator()(const FieldInfo& info, const T& value) const {
    const double v = static_cast<double>(value);
    if (!(v >= info.min_value && v <= info.max_value)) {
      throw ConfigError(Name(info) + " = " + std::to_string(v) + " is outside [" +
                        std::to_string(info.min_value) + ", " + std::to_string(info.max_value) +
                        "] " + info.unit);
    }
  }
  void operator()(const FieldInfo& info, const bool& /*value*/) const { (void)info; }
  void operator()(const FieldInfo& info, const std::string& value) const;

 private:
  std::string Name(const FieldInfo& info) const { return prefix_ + info.name; }
  std::string prefix_;
};

}  // namespace dslam
