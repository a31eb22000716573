// dslam_train_vocabulary: trains the place-recognition vocabulary (dslam/place_recognition/
// vocabulary.h) on the ORB descriptors of TUM-layout folders, extracted with the default Config's
// features (as the tracker sees them; --features sets features.num_features), every --stride-th
// frame of each folder, and writes the vocabulary file. Deterministic: the same folders and
// options give a byte-identical file (feature extraction does not depend on the thread count).
// Usage: dslam_train_vocabulary --out FILE [--branching 10] [--levels 5] [--iterations 10]
//        [--seed 1] [--stride 1] [--features 1000] [--threads 1] FOLDER...

#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <opencv2/core/utility.hpp>

#include "dataset_descriptors.h"
#include "dslam/core/stopwatch.h"
#include "dslam/place_recognition/vocabulary.h"

namespace {

struct Args {
  std::string out;
  std::vector<std::string> folders;
  dslam::VocabularyParams params;
  int stride = 1;
  int features = 1000;
  int threads = 1;
};

int Usage() {
  std::cerr << "usage: dslam_train_vocabulary --out FILE [--branching 10] [--levels 5] "
               "[--iterations 10] [--seed 1]\n"
               "                              [--stride 1] [--features 1000] [--threads 1] "
               "FOLDER...\n";
  return 2;
}

bool Parse(int argc, char** argv, Args* args) {
  for (int i = 1; i < argc; ++i) {
    const std::string key = argv[i];
    if (key.rfind("--", 0) != 0) {
      args->folders.push_back(key);
      continue;
    }
    if (i + 1 >= argc) return false;
    const std::string value = argv[++i];
    if (key == "--out")
      args->out = value;
    else if (key == "--branching")
      args->params.branching = std::stoi(value);
    else if (key == "--levels")
      args->params.levels = std::stoi(value);
    else if (key == "--iterations")
      args->params.max_iterations = std::stoi(value);
    else if (key == "--seed")
      args->params.seed = static_cast<std::uint32_t>(std::stoul(value));
    else if (key == "--stride")
      args->stride = std::stoi(value);
    else if (key == "--features")
      args->features = std::stoi(value);
    else if (key == "--threads")
      args->threads = std::stoi(value);
    else
      return false;
  }
  return !args->out.empty() && !args->folders.empty() && args->stride >= 1 && args->threads >= 1;
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
  cv::setNumThreads(args.threads);
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
  Args args;
  try {
    if (!Parse(argc, argv, &args)) return Usage();
    return Run(args);
  } catch (const std::exception& e) {
    std::cerr << "dslam_train_vocabulary: " << e.what() << "\n";
    return 1;
  }
}
