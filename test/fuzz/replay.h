#pragma once
// Replays the stored fuzz inputs of one target (test/fuzz/corpus/<target>/ and
// test/fuzz/regressions/<target>/) through its harness in a gtest: each input must be parsed or
// rejected as the code under test documents (the harness returns).

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace dslam {
namespace fuzz {

/// Files of test/fuzz/<kind>/<target>/, sorted; none when the folder does not exist.
inline std::vector<std::string> StoredInputs(const std::string& kind, const std::string& target) {
  const std::filesystem::path folder =
      std::filesystem::path(DSLAM_SOURCE_DIR) / "test" / "fuzz" / kind / target;
  std::vector<std::string> files;
  if (!std::filesystem::is_directory(folder)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.is_regular_file()) files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// Runs `harness` on every stored input of `target`; fails on an input it throws for, and when
/// the target has no seed corpus.
template <typename Harness>
void ReplayStoredInputs(const std::string& target, Harness harness) {
  const std::vector<std::string> corpus = StoredInputs("corpus", target);
  EXPECT_FALSE(corpus.empty()) << "no seed corpus for " << target;
  std::vector<std::string> inputs = corpus;
  for (const std::string& file : StoredInputs("regressions", target)) inputs.push_back(file);
  for (const std::string& file : inputs) {
    std::ifstream in(file, std::ios::binary);
    ASSERT_TRUE(in) << file;
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    try {
      harness(bytes);
    } catch (const std::exception& e) {
      ADD_FAILURE() << file << ": " << e.what();
    }
  }
}

}  // namespace fuzz
}  // namespace dslam
