#pragma once
// A hierarchical vocabulary tree of 32-byte binary (ORB) descriptors, as DBoW2's
// (Galvez-Lopez and Tardos 2012): each inner node has up to `branching` children, found by
// k-majority clustering (k-medians under the Hamming distance: a centre's bit is the majority bit
// of its members) seeded with k-means++; the leaves, at most `levels` below the root, are the
// words, each with an idf weight. Training, the tree and the file format are this part's own code.
//
// Training is deterministic: every node's clustering draws from a std::mt19937 seeded with
// std::seed_seq{seed, node id}, with integer arithmetic only; no threads, no hash-order
// dependence. The same descriptors and parameters give a byte-identical file.
//
// File format (all integers little-endian; version 1):
//   offset  0  8 bytes  magic "DSLAMVOC"
//           8  uint32   format version (kFormatVersion)
//          12  uint64   identity: 64-bit FNV-1a hash of every byte from offset 20 to the end
//          20  uint32   branching k, uint32 levels L, uint32 descriptor bytes (32),
//                       uint32 number of nodes, uint32 number of words
//          40  nodes, 44 bytes each, in node order (root first, every node after its parent, the
//              children of one node consecutive): uint32 parent (0xFFFFFFFF for the root),
//              float64 weight (a word's idf; 0 for inner nodes), 32 bytes descriptor (root: 0).
// The words are the leaves (nodes without children) in node order.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "dslam/core/binary_io.h"  // FormatIdentity, how tools print identity()
#include "dslam/place_recognition/bow_vector.h"

namespace dslam {

struct VocabularyTree;  // the tree's arrays (src/place_recognition/vocabulary_tree.h)

/// Parameters of Vocabulary::Train.
struct VocabularyParams {
  int branching = 10;       ///< k: children per inner node, >= 2
  int levels = 5;           ///< L: depth of the deepest words below the root, >= 1
  int max_iterations = 10;  ///< k-majority rounds per node after seeding (fewer on convergence)
  std::uint32_t seed = 1;   ///< seed of every node's random generator
};

/// An immutable vocabulary tree; copies share the tree. A default-constructed one is empty.
class Vocabulary {
 public:
  /// Bytes per descriptor (ORB: 256 bits).
  static constexpr int kDescriptorBytes = 32;
  /// Version written by Save and the only one Load accepts.
  static constexpr std::uint32_t kFormatVersion = 1;

  Vocabulary() = default;

  /// Trains a vocabulary on the descriptors of a set of images (each CV_8UC1, 32 columns, one
  /// descriptor per row; images without rows count for the idf). idf of a word = ln(N / n), N the
  /// number of images, n those with a descriptor in that word (at least 1). Throws
  /// std::invalid_argument on bad parameters or descriptors, or when there is no descriptor.
  static Vocabulary Train(const std::vector<cv::Mat>& images, const VocabularyParams& params);

  /// Reads a file written by Save. Throws std::runtime_error naming the file and the reason
  /// (cannot be opened, truncated, wrong magic, unsupported version, corrupt contents).
  static Vocabulary Load(const std::string& path);

  /// Writes the file format above to `path`: to a temporary file beside it first, renamed to
  /// `path` once complete. Throws std::runtime_error naming the file when it fails.
  void Save(const std::string& path) const;

  /// The bag of words of an image's descriptors (CV_8UC1, 32 columns): each descriptor goes down
  /// the tree to the nearest child (Hamming distance; ties: the first) until a word;
  /// weight = count * idf, then L1-normalised. Throws std::invalid_argument on bad descriptors,
  /// std::logic_error on an empty vocabulary.
  BowVector Transform(const cv::Mat& descriptors) const;

  /// The word of one descriptor (32 bytes at `descriptor`).
  WordId WordOf(const std::uint8_t* descriptor) const;

  bool empty() const { return tree_ == nullptr; }  ///< true before Train or Load
  int branching() const;                           ///< k
  int levels() const;                              ///< L
  std::size_t num_nodes() const;                   ///< nodes including the root
  std::size_t num_words() const;                   ///< leaves
  double WordWeight(WordId word) const;            ///< idf [-] of `word`
  /// 64-bit FNV-1a hash of the file's contents after the header's identity field: equal for
  /// equal vocabularies, whether trained or loaded; 0 when empty.
  std::uint64_t identity() const;

 private:
  explicit Vocabulary(std::shared_ptr<const VocabularyTree> tree) : tree_(std::move(tree)) {}

  std::shared_ptr<const VocabularyTree> tree_;
};

/// The committed vocabulary, data/vocabulary/orb_vocabulary.bin in the source tree this library
/// was built from (installed to the package's share folder as data/vocabulary/).
std::string DefaultVocabularyPath();

}  // namespace dslam
