// dslam_train_vocabulary: trains the place-recognition vocabulary (dslam/place_recognition/
// vocabulary.h) on the ORB descriptors of TUM-layout folders, extracted with the default Config's
// features (as the tracker sees them; --features sets features.num_features), every --stride-th
// frame of each folder, and writes the vocabulary file. Deterministic: the same folders and
// options give a byte-identical file (feature extraction does not depend on the thread count).
// Usage: kUsage below.

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/core/utility.hpp>

#include "dataset_descriptors.h"
#include "dslam/core/stopwatch.h"
#include "dslam/place_recognition/vocabulary.h"
#include "eval_tool.h"

namespace {

constexpr char kUsage[] =
    "usage: dslam_train_vocabulary --datasets FOLDER[,FOLDER...] --out FILE [--branching 10]\n"
    "                              [--levels 5] [--iterations 10] [--seed 1] [--stride 1]\n"
    "                              [--features 1000] [--threads 1]\n"
    "  --datasets    TUM-layout folders (rgb.txt, depth.txt, camera.yaml), comma-separated\n"
    "  --out         the vocabulary file to write\n"
    "  --branching   k: children per node; --levels L: depth of the tree\n"
    "  --iterations  k-majority rounds per node; --seed: the random generators' seed\n"
    "  --stride      every stride-th frame of each folder; --features ORB features per frame\n"
    "  --threads     OpenCV threads of the feature extraction (the file does not depend on it)\n";

struct Args {
  std::string out;
  std::vector<std::string> folders;
  dslam::VocabularyParams params;
  int stride = 1;
  int features = 1000;
};

// A whole-number option (> 0) or its default.
int Whole(const dslam::tools::Options& options, const std::string& name, int fallback) {
  return static_cast<int>(dslam::tools::NumberOption(options, name, fallback,
                                                     dslam::tools::NumberKind::kPositiveWhole));
}

Args ReadArgs(const dslam::tools::Options& options) {
  Args args;
  std::stringstream folders(options.at("datasets"));
  for (std::string folder; std::getline(folders, folder, ',');) {
    if (!folder.empty()) args.folders.push_back(folder);
  }
  args.out = options.at("out");
  args.params = {Whole(options, "branching", 10), Whole(options, "levels", 5),
                 Whole(options, "iterations", 10),
                 static_cast<std::uint32_t>(Whole(options, "seed", 1))};
  args.stride = Whole(options, "stride", 1);
  args.features = Whole(options, "features", 1000);
  cv::setNumThreads(Whole(options, "threads", 1));
  return args;
}

// Every stride-th frame's descriptors of every folder, in the order given.
std::vector<cv::Mat> ReadDescriptors(const Args& args, const dslam::Config& config) {
  std::vector<cv::Mat> images;
  for (const std::string& folder : args.folders) {
    const dslam::TumDataset dataset(folder, "", config.dataset.association_max_dt_s);
    const std::vector<int> frames =
        dslam::tools::FrameIndices({0, -1, args.stride}, dataset.size());
    size_t descriptors = 0;
    for (const int index : frames) {
      images.push_back(dslam::tools::FrameDescriptors(dataset, index, config));
      descriptors += images.back().rows;
    }
    std::printf("%s: %zu images, %zu descriptors\n", folder.c_str(), frames.size(), descriptors);
  }
  return images;
}

int Run(const Args& args) {
  dslam::Config config;
  config.features.num_features = args.features;
  const dslam::Stopwatch total;
  const std::vector<cv::Mat> images = ReadDescriptors(args, config);
  const double extract_s = total.ElapsedMs() / 1000.0;
  const dslam::Stopwatch training;
  const dslam::Vocabulary vocabulary = dslam::Vocabulary::Train(images, args.params);
  const double train_s = training.ElapsedMs() / 1000.0;
  vocabulary.Save(args.out);
  size_t descriptors = 0;
  for (const cv::Mat& image : images) descriptors += image.rows;
  std::printf(
      "vocabulary: %zu images, %zu descriptors, k %d, L %d, %zu nodes, %zu words, identity %s; "
      "extraction %.1f s, training %.1f s -> %s\n",
      images.size(), descriptors, vocabulary.branching(), vocabulary.levels(),
      vocabulary.num_nodes(), vocabulary.num_words(),
      dslam::FormatIdentity(vocabulary.identity()).c_str(), extract_s, train_s, args.out.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return dslam::tools::RunTool("dslam_train_vocabulary", kUsage, argc, argv,
                               {"datasets", "out", "branching", "levels", "iterations", "seed",
                                "stride", "features", "threads"},
                               {"datasets", "out"}, [](const dslam::tools::Options& options) {
                                 return Run(ReadArgs(options));
                               });
}
