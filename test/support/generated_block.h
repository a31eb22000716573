#pragma once
// Reads the text between two marker lines of a repository file (a table that
// scripts/update_readme.sh generates into docs/parameters.md), for tests that compare it with
// what the code generates now.

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace dslam {
namespace test {

/// The text of `path` (relative to the repository, DSLAM_SOURCE_DIR) after the line `begin` and
/// before `end`; throws std::runtime_error when the file or a marker is missing.
inline std::string GeneratedBlock(const std::string& path, const std::string& begin,
                                  const std::string& end) {
  std::ifstream in(std::string(DSLAM_SOURCE_DIR) + "/" + path);
  if (!in.good()) throw std::runtime_error("cannot read " + path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t start = text.find(begin + "\n");
  const size_t stop = text.find(end, start == std::string::npos ? 0 : start);
  if (start == std::string::npos || stop == std::string::npos) {
    throw std::runtime_error(path + " has no block between '" + begin + "' and '" + end + "'");
  }
  return text.substr(start + begin.size() + 1, stop - start - begin.size() - 1);
}

}  // namespace test
}  // namespace dslam
