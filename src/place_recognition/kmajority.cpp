#include "kmajority.h"

#include <algorithm>
#include <numeric>

#include "dslam/features/matching.h"

namespace dslam {
namespace {

constexpr int kBits = 8 * Vocabulary::kDescriptorBytes;

std::uint64_t SquaredDistance(const Descriptor& a, const Descriptor& b) {
  const std::uint64_t d = static_cast<std::uint64_t>(Hamming(a.data(), b.data()));
  return d * d;
}

// Uniform in [0, n) from two 32-bit draws (n > 0); the modulo bias is below 2^-32 for n < 2^32.
std::uint64_t UniformBelow(std::uint64_t n, std::mt19937* rng) {
  const std::uint64_t high = (*rng)();
  const std::uint64_t r = (high << 32) | (*rng)();
  return r % n;
}

// k-means++: the first seed uniformly, each next one with probability proportional to its squared
// distance to the nearest seed so far; stops early when every descriptor is a seed already.
std::vector<Descriptor> SeedCentres(const std::vector<Descriptor>& all,
                                    const std::vector<std::uint32_t>& subset, int k,
                                    std::mt19937* rng) {
  std::vector<Descriptor> centres{all[subset[UniformBelow(subset.size(), rng)]]};
  std::vector<std::uint64_t> d2(subset.size());
  for (size_t i = 0; i < subset.size(); ++i) d2[i] = SquaredDistance(all[subset[i]], centres[0]);
  while (static_cast<int>(centres.size()) < k) {
    const std::uint64_t total = std::accumulate(d2.begin(), d2.end(), std::uint64_t{0});
    if (total == 0) break;
    std::uint64_t target = UniformBelow(total, rng);
    size_t pick = 0;
    while (target >= d2[pick]) target -= d2[pick++];
    centres.push_back(all[subset[pick]]);
    for (size_t i = 0; i < subset.size(); ++i) {
      d2[i] = std::min(d2[i], SquaredDistance(all[subset[i]], centres.back()));
    }
  }
  return centres;
}

// Assigns every descriptor to its nearest centre (ties: the lower index); true when any changed.
bool Assign(const std::vector<Descriptor>& all, const std::vector<std::uint32_t>& subset,
            const std::vector<Descriptor>& centres, std::vector<int>* assignment) {
  bool changed = false;
  for (size_t i = 0; i < subset.size(); ++i) {
    int best = 0;
    int best_distance = kBits + 1;
    for (size_t c = 0; c < centres.size(); ++c) {
      const int d = Hamming(all[subset[i]].data(), centres[c].data());
      if (d < best_distance) {
        best_distance = d;
        best = static_cast<int>(c);
      }
    }
    if ((*assignment)[i] != best) changed = true;
    (*assignment)[i] = best;
  }
  return changed;
}

// Every non-empty centre becomes the bitwise majority of its members (ties: 0).
void UpdateCentres(const std::vector<Descriptor>& all, const std::vector<std::uint32_t>& subset,
                   const std::vector<int>& assignment, std::vector<Descriptor>* centres) {
  std::vector<std::uint32_t> ones(centres->size() * kBits, 0);
  std::vector<std::uint32_t> sizes(centres->size(), 0);
  for (size_t i = 0; i < subset.size(); ++i) {
    const Descriptor& d = all[subset[i]];
    std::uint32_t* count = &ones[assignment[i] * kBits];
    ++sizes[assignment[i]];
    for (int byte = 0; byte < Vocabulary::kDescriptorBytes; ++byte) {
      for (int bit = 0; bit < 8; ++bit) count[byte * 8 + bit] += (d[byte] >> bit) & 1u;
    }
  }
  for (size_t c = 0; c < centres->size(); ++c) {
    if (sizes[c] == 0) continue;
    const std::uint32_t* count = &ones[c * kBits];
    Descriptor& centre = (*centres)[c];
    for (int byte = 0; byte < Vocabulary::kDescriptorBytes; ++byte) {
      std::uint8_t value = 0;
      for (int bit = 0; bit < 8; ++bit) {
        if (2 * count[byte * 8 + bit] > sizes[c]) value |= static_cast<std::uint8_t>(1u << bit);
      }
      centre[byte] = value;
    }
  }
}

}  // namespace

Clusters ClusterKMajority(const std::vector<Descriptor>& all,
                          const std::vector<std::uint32_t>& subset, int k, int max_iterations,
                          std::mt19937* rng) {
  Clusters clusters;
  if (subset.empty()) return clusters;
  std::vector<Descriptor> centres = SeedCentres(all, subset, k, rng);
  std::vector<int> assignment(subset.size(), -1);
  bool changed = Assign(all, subset, centres, &assignment);
  for (int round = 0; round < max_iterations && changed; ++round) {
    UpdateCentres(all, subset, assignment, &centres);
    changed = Assign(all, subset, centres, &assignment);
  }
  std::vector<std::vector<std::uint32_t>> members(centres.size());
  for (size_t i = 0; i < subset.size(); ++i) members[assignment[i]].push_back(subset[i]);
  for (size_t c = 0; c < centres.size(); ++c) {
    if (members[c].empty()) continue;
    clusters.centres.push_back(centres[c]);
    clusters.members.push_back(std::move(members[c]));
  }
  return clusters;
}

}  // namespace dslam
