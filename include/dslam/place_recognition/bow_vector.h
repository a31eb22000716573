#pragma once
// Bag-of-words vectors over a vocabulary of binary descriptors (vocabulary.h) and their L1 score
// (Nister and Stewenius 2006; as DBoW2 scores ORB-SLAM2's keyframes).

#include <cstdint>
#include <map>
#include <vector>

namespace dslam {

/// Index of a word (a leaf of the vocabulary tree), 0 .. Vocabulary::num_words() - 1.
using WordId = std::uint32_t;
/// Index of a node of the vocabulary tree, 0 (the root) .. Vocabulary::num_nodes() - 1.
using NodeId = std::uint32_t;

/// Word -> weight [-] (tf-idf) of one image, sorted by word; words of weight 0 are left out.
using BowVector = std::map<WordId, double>;

/// Divides every weight by the sum of their absolute values (nothing when that sum is 0).
void NormaliseL1(BowVector* v);

/// L1 score 1 - 0.5 * |a/|a|_1 - b/|b|_1|_1 in [0, 1]: 1 for vectors with the same direction, 0
/// for vectors without a common word (and when either is empty).
double ScoreL1(const BowVector& a, const BowVector& b);

}  // namespace dslam
