// Vocabulary::Train: the tree grown depth-first by k-majority clustering (kmajority.h), then the
// words' idf over the training images.

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "dslam/core/binary_io.h"
#include "dslam/place_recognition/vocabulary.h"
#include "kmajority.h"
#include "vocabulary_tree.h"

namespace dslam {
namespace {

void CheckParams(const VocabularyParams& params) {
  if (params.branching < 2 || params.levels < 1 || params.max_iterations < 0) {
    throw std::invalid_argument(
        "Vocabulary::Train: needs branching >= 2, levels >= 1, max_iterations >= 0");
  }
  if (std::pow(static_cast<double>(params.branching), params.levels) > 1e8) {
    throw std::invalid_argument("Vocabulary::Train: branching^levels above 1e8 words");
  }
}

std::vector<Descriptor> Flatten(const std::vector<cv::Mat>& images) {
  std::vector<Descriptor> all;
  for (const cv::Mat& image : images) {
    if (image.empty()) continue;
    if (image.type() != CV_8UC1 || image.cols != Vocabulary::kDescriptorBytes) {
      throw std::invalid_argument("Vocabulary::Train: descriptors must be CV_8UC1, 32 columns");
    }
    for (int row = 0; row < image.rows; ++row) {
      Descriptor d;
      std::memcpy(d.data(), image.ptr<std::uint8_t>(row), d.size());
      all.push_back(d);
    }
  }
  if (all.empty()) throw std::invalid_argument("Vocabulary::Train: no descriptors");
  return all;
}

// Grows the tree below `node` (at `depth`) from the descriptors all[members[i]]: the node stays a
// word at depth L or when its descriptors form a single cluster.
void Grow(const std::vector<Descriptor>& all, const VocabularyParams& params, std::uint32_t node,
          int depth, const std::vector<std::uint32_t>& members, VocabularyTree* tree) {
  if (depth >= params.levels || members.size() <= 1) return;
  std::seed_seq seeds{params.seed, node};
  std::mt19937 rng(seeds);
  Clusters clusters = ClusterKMajority(all, members, params.branching, params.max_iterations, &rng);
  if (clusters.centres.size() <= 1) return;
  const std::uint32_t first = static_cast<std::uint32_t>(tree->parent.size());
  for (const Descriptor& centre : clusters.centres) tree->AddNode(node, centre);
  for (size_t c = 0; c < clusters.centres.size(); ++c) {
    const std::vector<std::uint32_t> child_members = std::move(clusters.members[c]);
    Grow(all, params, first + static_cast<std::uint32_t>(c), depth + 1, child_members, tree);
  }
}

// idf = ln(N / n) per word: N images, n of them with a descriptor in the word (at least 1).
void SetIdf(const std::vector<cv::Mat>& images, VocabularyTree* tree) {
  std::vector<std::uint32_t> images_with(tree->node_of_word.size(), 0);
  std::vector<std::uint32_t> last_image(tree->node_of_word.size(), kNoNode);
  for (size_t i = 0; i < images.size(); ++i) {
    for (int row = 0; row < images[i].rows; ++row) {
      const std::uint32_t word = Descend(*tree, images[i].ptr<std::uint8_t>(row));
      if (last_image[word] == i) continue;
      last_image[word] = static_cast<std::uint32_t>(i);
      ++images_with[word];
    }
  }
  const double n_images = static_cast<double>(images.size());
  for (size_t w = 0; w < images_with.size(); ++w) {
    tree->weight[tree->node_of_word[w]] = std::log(n_images / std::max(1u, images_with[w]));
  }
}

}  // namespace

Vocabulary Vocabulary::Train(const std::vector<cv::Mat>& images, const VocabularyParams& params) {
  CheckParams(params);
  const std::vector<Descriptor> all = Flatten(images);
  auto tree = std::make_shared<VocabularyTree>();
  tree->branching = params.branching;
  tree->levels = params.levels;
  tree->AddNode(kNoNode, Descriptor{});
  std::vector<std::uint32_t> members(all.size());
  for (size_t i = 0; i < all.size(); ++i) members[i] = static_cast<std::uint32_t>(i);
  Grow(all, params, 0, 0, members, tree.get());
  const std::string problem = tree->Index();
  if (!problem.empty()) {
    throw std::invalid_argument("Vocabulary::Train: " + problem + " (all descriptors equal?)");
  }
  SetIdf(images, tree.get());
  const std::string body = SerialiseBody(*tree);
  tree->identity = Fnv1a64(body.data(), body.size());
  return Vocabulary(std::move(tree));
}

}  // namespace dslam
