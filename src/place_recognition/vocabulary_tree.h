#pragma once
// The arrays of a vocabulary tree (vocabulary.h), shared by training (vocabulary_training.cpp),
// the file format (vocabulary_file.cpp) and Transform (vocabulary.cpp). Internal to the part.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dslam/place_recognition/bow_vector.h"
#include "dslam/place_recognition/vocabulary.h"

namespace dslam {

/// One 32-byte binary descriptor.
using Descriptor = std::array<std::uint8_t, Vocabulary::kDescriptorBytes>;

/// Parent of the root; also "no word" in VocabularyTree::word_of_node.
constexpr std::uint32_t kNoNode = 0xFFFFFFFFu;

struct VocabularyTree {
  int branching = 0;                        // k
  int levels = 0;                           // L
  std::vector<std::uint32_t> parent;        // per node; kNoNode for the root (node 0)
  std::vector<Descriptor> descriptor;       // per node; the root's is all zeros
  std::vector<double> weight;               // per node; a word's idf, 0 for inner nodes
  std::vector<std::uint32_t> first_child;   // per node (Index)
  std::vector<std::uint32_t> num_children;  // per node (Index)
  std::vector<std::uint32_t> word_of_node;  // per node (Index); kNoNode for inner nodes
  std::vector<std::uint32_t> node_of_word;  // per word (Index)
  std::uint64_t identity = 0;               // ContentIdentity, set once the tree is complete

  /// Appends a node below `parent_node` (kNoNode: the root); returns its id.
  std::uint32_t AddNode(std::uint32_t parent_node, const Descriptor& d);

  /// Fills first_child, num_children, word_of_node and node_of_word from `parent`. Returns an
  /// empty string, or what is wrong: a parent after its child, children not consecutive, more
  /// than `branching` children, a node deeper than `levels`.
  std::string Index();
};

/// The file's bytes from offset 20 to the end (vocabulary.h): parameters and nodes.
std::string SerialiseBody(const VocabularyTree& tree);

/// The word of one descriptor: down the tree to the nearest child (Hamming distance; ties: the
/// first) until a leaf.
std::uint32_t Descend(const VocabularyTree& tree, const std::uint8_t* d);

}  // namespace dslam
