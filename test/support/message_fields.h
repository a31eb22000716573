#pragma once
// Reads the fields of a ROS .msg file of the repository, for tests that check a message
// definition against the code that fills it.

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace dslam {
namespace test {

/// Type and name of each field of `path` (relative to the repository, DSLAM_SOURCE_DIR), in
/// order; comments and blank lines skipped. Throws std::runtime_error when the file is missing.
inline std::vector<std::pair<std::string, std::string>> MessageFields(const std::string& path) {
  std::ifstream in(std::string(DSLAM_SOURCE_DIR) + "/" + path);
  if (!in.good()) throw std::runtime_error("cannot read " + path);
  std::vector<std::pair<std::string, std::string>> fields;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string type, name;
    if (words >> type >> name) fields.emplace_back(type, name);
  }
  return fields;
}

}  // namespace test
}  // namespace dslam
