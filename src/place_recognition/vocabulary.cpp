#include "dslam/place_recognition/vocabulary.h"

#include <algorithm>
#include <stdexcept>

#include "vocabulary_tree.h"

namespace dslam {
namespace {

void CheckDescriptors(const cv::Mat& descriptors, const char* where) {
  if (descriptors.empty()) return;
  if (descriptors.type() != CV_8UC1 || descriptors.cols != Vocabulary::kDescriptorBytes) {
    throw std::invalid_argument(std::string(where) +
                                ": descriptors must be CV_8UC1 with 32 columns");
  }
}

}  // namespace

BowVector Vocabulary::Transform(const cv::Mat& descriptors) const {
  if (empty()) throw std::logic_error("Vocabulary::Transform: empty vocabulary");
  CheckDescriptors(descriptors, "Vocabulary::Transform");
  BowVector words;
  for (int row = 0; row < descriptors.rows; ++row) {
    const std::uint32_t word = Descend(*tree_, descriptors.ptr<std::uint8_t>(row));
    const double idf = tree_->weight[tree_->node_of_word[word]];
    if (idf > 0.0) words[word] += idf;
  }
  NormaliseL1(&words);
  return words;
}

WordId Vocabulary::WordOf(const std::uint8_t* descriptor) const {
  if (empty()) throw std::logic_error("Vocabulary::WordOf: empty vocabulary");
  return Descend(*tree_, descriptor);
}

int Vocabulary::branching() const { return empty() ? 0 : tree_->branching; }
int Vocabulary::levels() const { return empty() ? 0 : tree_->levels; }
std::size_t Vocabulary::num_nodes() const { return empty() ? 0 : tree_->parent.size(); }
std::size_t Vocabulary::num_words() const { return empty() ? 0 : tree_->node_of_word.size(); }
std::uint64_t Vocabulary::identity() const { return empty() ? 0 : tree_->identity; }

double Vocabulary::WordWeight(WordId word) const {
  if (word >= num_words()) throw std::out_of_range("Vocabulary::WordWeight: no such word");
  return tree_->weight[tree_->node_of_word[word]];
}

}  // namespace dslam
