// Fuzz harness: a TUM folder (dslam/io/dataset_io.h, TumDataset): the bytes are the folder's
// camera.yaml, rgb.txt and depth.txt, separated by NUL bytes, written to a temporary folder.
#include <yaml-cpp/exceptions.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "dslam/io/dataset_io.h"
#include "fuzz_input.h"
#include "harnesses.h"

namespace dslam {
namespace fuzz {
namespace {

constexpr double kMaxDtS = 0.02;  // the default dataset.association_max_dt_s [s]
const char* const kFiles[] = {"camera.yaml", "rgb.txt", "depth.txt"};

/// A temporary folder of this process, removed with its three files at exit.
class TempFolder {
 public:
  TempFolder() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/dslam_fuzz_tum_XXXXXX";
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed: " + pattern);
    path_ = pattern;
  }
  ~TempFolder() {
    for (const char* file : kFiles) std::remove((path_ + "/" + file).c_str());
    rmdir(path_.c_str());
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

void WriteFile(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path);
}

/// Entries of a file list as ParseFileList reads them; -1 when it rejects the list.
long ListSize(const std::string& text) {
  std::istringstream in(text);
  try {
    return static_cast<long>(ParseFileList(in, "list").size());
  } catch (const std::runtime_error&) {
    return -1;
  }
}

}  // namespace

void TumDatasetHarness(const std::string& data) {
  static const TempFolder folder;
  FuzzInput input(data);
  std::string texts[3];
  for (int i = 0; i < 3; ++i) {
    texts[i] = input.UntilNul();
    WriteFile(folder.path() + "/" + kFiles[i], texts[i]);
  }
  ParsedOrRejected<std::runtime_error>(folder.path(), [&] {
    try {
      const TumDataset dataset(folder.path(), "", kMaxDtS);
      CheckCamera(*dataset.camera_yaml().camera);
      const long colour = ListSize(texts[1]), depth = ListSize(texts[2]);
      if (colour < 0 || depth < 0) throw ContractViolation("accepted a malformed file list");
      if (static_cast<long>(dataset.size()) > std::min(colour, depth)) {
        throw ContractViolation("more pairs than colour or depth entries");
      }
      for (size_t i = 0; i < dataset.size(); ++i) {
        const AssociatedPair& pair = dataset.pairs()[i];
        if (!(std::abs(pair.colour.stamp_s - pair.depth.stamp_s) <= kMaxDtS)) {
          throw ContractViolation("pair beyond the association tolerance");
        }
        if (i > 0 && pair.colour.stamp_s < dataset.pairs()[i - 1].colour.stamp_s) {
          throw ContractViolation("pairs not sorted by colour stamp");
        }
      }
    } catch (const YAML::Exception& e) {
      throw ContractViolation(std::string("yaml-cpp exception escaped: ") + e.what());
    }
  });
}

}  // namespace fuzz
}  // namespace dslam

DSLAM_FUZZ_TARGET(dslam::fuzz::TumDatasetHarness)
