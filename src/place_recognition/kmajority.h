#pragma once
// k-majority clustering of binary descriptors: k-medians under the Hamming distance, where a
// centre's bit is the majority bit of its members (ties: 0), seeded with k-means++ (each further
// seed drawn with probability proportional to its squared distance to the nearest seed so far).
// Integer arithmetic and a given std::mt19937 only: the result depends on nothing else.
// Internal to the place_recognition part (vocabulary_training.cpp).

#include <cstdint>
#include <random>
#include <vector>

#include "vocabulary_tree.h"

namespace dslam {

/// Clusters found by ClusterKMajority.
struct Clusters {
  std::vector<Descriptor> centres;                  // at most k, none empty
  std::vector<std::vector<std::uint32_t>> members;  // per centre: indices into the descriptors
};

/// Clusters the descriptors all[subset[i]] into at most `k` clusters: seeding, then up to
/// `max_iterations` rounds of centre update and assignment (each descriptor to the nearest
/// centre, ties: the lower index), stopping early when no assignment changes. Fewer than `k`
/// clusters when there are fewer distinct descriptors; empty clusters are dropped, the others
/// keep their order. Every member is nearest (ties: first) to its own centre.
Clusters ClusterKMajority(const std::vector<Descriptor>& all,
                          const std::vector<std::uint32_t>& subset, int k, int max_iterations,
                          std::mt19937* rng);

}  // namespace dslam
