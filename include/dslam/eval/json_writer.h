#pragma once
// A small JSON writer for the result files of the command-line tools (dslam_eval --json,
// dslam_run_dataset --summary): objects whose members are strings, integers, numbers, booleans or
// nested objects, in the order they were added. Layout: "{", one member `"key": value` per line
// indented by two spaces per nesting level, members separated by ",", "}" on its own line; an
// empty object is "{}". test/eval/json_writer_test.cpp checks the exact text.

#include <string>
#include <utility>
#include <vector>

namespace dslam {

/// `text` as a JSON string literal, quotes included: '"' and '\' are escaped with a backslash,
/// bytes below 0x20 are written as \u00XX (lower-case hex); all other bytes (e.g. UTF-8) are
/// copied unchanged.
std::string JsonString(const std::string& text);

/// `value` as a JSON number in printf's "%.*g" with `significant_digits` [-] (e.g. 0.1 -> "0.1",
/// 1234567 with 6 digits -> "1.23457e+06"); "null" for NaN and infinities, which JSON cannot
/// represent.
std::string JsonNumber(double value, int significant_digits);

/// A JSON object built member by member; keys are written as given (not checked for duplicates).
class JsonObject {
 public:
  /// Adds a string member (escaped by JsonString()).
  JsonObject& AddString(const std::string& key, const std::string& value);

  /// Adds an integer member, written in decimal.
  JsonObject& AddInteger(const std::string& key, long long value);

  /// Adds a number member, written by JsonNumber(value, significant_digits).
  JsonObject& AddNumber(const std::string& key, double value, int significant_digits);

  /// Adds a boolean member, written as true or false.
  JsonObject& AddBool(const std::string& key, bool value);

  /// Adds a nested object member (a copy of `value` as it is now).
  JsonObject& AddObject(const std::string& key, const JsonObject& value);

  /// The object's text in the layout described at the top of this header, without a final
  /// newline.
  std::string ToString() const;

 private:
  std::vector<std::pair<std::string, std::string>> members_;  ///< key, value's text at level 0
};

/// Writes object.ToString() and a newline to `path` (replacing the file). Throws
/// std::runtime_error("cannot write PATH") when the file cannot be opened and
/// std::runtime_error("error while writing PATH") when writing fails.
void WriteJsonFile(const std::string& path, const JsonObject& object);

}  // namespace dslam
