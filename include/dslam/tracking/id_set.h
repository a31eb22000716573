#pragma once
// A set of map point ids for the per-frame de-duplications of the tracking part: open
// addressing with linear probing in one array sized once, so inserting allocates nothing
// (std::unordered_set allocates a node per element).

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "dslam/tracking/map.h"

namespace dslam {

/// Set of non-negative PointIds with room for at least `capacity` elements.
class IdSet {
 public:
  explicit IdSet(size_t capacity) {
    size_t slots = 16;
    while (slots < 2 * capacity) slots <<= 1;  // load factor <= 0.5
    slots_.assign(slots, kEmpty);
    mask_ = slots - 1;
    shift_ = 64;
    for (size_t s = slots; s > 1; s >>= 1) --shift_;
  }

  /// Inserts `id` (>= 0); false when it was in the set already. Throws std::length_error when
  /// the set would fill more than half of its slots (`capacity` elements always fit).
  bool Insert(PointId id) {
    for (size_t slot = Slot(id);; slot = (slot + 1) & mask_) {
      if (slots_[slot] == id) return false;
      if (slots_[slot] == kEmpty) {
        if (2 * (size_ + 1) > slots_.size()) throw std::length_error("IdSet: capacity exceeded");
        slots_[slot] = id;
        ++size_;
        return true;
      }
    }
  }

  /// Whether `id` is in the set.
  bool Contains(PointId id) const {
    for (size_t slot = Slot(id);; slot = (slot + 1) & mask_) {
      if (slots_[slot] == id) return true;
      if (slots_[slot] == kEmpty) return false;
    }
  }

  size_t size() const { return size_; }  ///< number of elements

 private:
  static constexpr PointId kEmpty = -1;
  // Fibonacci hashing: the top bits of id * 2^64 / golden ratio.
  size_t Slot(PointId id) const {
    return static_cast<size_t>((static_cast<uint64_t>(id) * 0x9E3779B97F4A7C15ull) >> shift_) &
           mask_;
  }

  std::vector<PointId> slots_;
  size_t mask_ = 0;
  int shift_ = 64;
  size_t size_ = 0;
};

}  // namespace dslam
