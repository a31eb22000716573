#include "dslam/eval/json_writer.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace dslam {
namespace {

// `text` with `indent` inserted after every newline. The value texts of members contain newlines
// only between lines of a nested object (JsonString() escapes newlines in strings), so this indents
// a nested object by one level.
std::string IndentLines(const std::string& text, const std::string& indent) {
  std::string out;
  for (char ch : text) {
    out += ch;
    if (ch == '\n') out += indent;
  }
  return out;
}

}  // namespace

std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (char ch : text) {
    const unsigned int byte = static_cast<unsigned char>(ch);
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (byte < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof(buffer), "\\u%04x", byte);
      out += buffer;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

std::string JsonNumber(double value, int significant_digits) {
  if (!std::isfinite(value)) return "null";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*g", significant_digits, value);
  return buffer;
}

JsonObject& JsonObject::AddString(const std::string& key, const std::string& value) {
  members_.emplace_back(key, JsonString(value));
  return *this;
}

JsonObject& JsonObject::AddInteger(const std::string& key, long long value) {
  members_.emplace_back(key, std::to_string(value));
  return *this;
}

JsonObject& JsonObject::AddNumber(const std::string& key, double value, int significant_digits) {
  members_.emplace_back(key, JsonNumber(value, significant_digits));
  return *this;
}

JsonObject& JsonObject::AddBool(const std::string& key, bool value) {
  members_.emplace_back(key, value ? "true" : "false");
  return *this;
}

JsonObject& JsonObject::AddObject(const std::string& key, const JsonObject& value) {
  members_.emplace_back(key, value.ToString());
  return *this;
}

std::string JsonObject::ToString() const {
  if (members_.empty()) return "{}";
  const std::string indent = "  ";
  std::string out = "{";
  for (size_t i = 0; i < members_.size(); ++i) {
    out += i == 0 ? "\n" : ",\n";
    out += indent + JsonString(members_[i].first) + ": " + IndentLines(members_[i].second, indent);
  }
  return out + "\n}";
}

void WriteJsonFile(const std::string& path, const JsonObject& object) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << object.ToString() << "\n";
  if (!out) throw std::runtime_error("error while writing " + path);
}

}  // namespace dslam
