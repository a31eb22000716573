#pragma once
// A small bounded mailbox between the subscriber callback and the processing thread: Put() never
// blocks; when `capacity` items wait already, the oldest is dropped (and counted). Take() blocks
// until an item arrives or Close() is called. Keeps the callback short whatever the processing
// time; a capacity of 2 absorbs the bursts of message_filters' ApproximateTime policy (which can
// release two synchronized sets at once) while a slow node still works on recent frames.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <utility>

namespace dslam {
namespace ros_layer {

template <typename T>
class LatestSlot {
 public:
  /// `capacity` >= 1 items may wait; more drop the oldest.
  explicit LatestSlot(size_t capacity = 2) : capacity_(capacity < 1 ? 1 : capacity) {}

  /// Stores `item`; returns true when an older waiting item was dropped to make room.
  bool Put(T item) {
    bool dropped = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (items_.size() >= capacity_) {
        items_.pop_front();
        dropped = true;
        ++dropped_;
      }
      items_.push_back(std::move(item));
    }
    ready_.notify_one();
    return dropped;
  }

  /// Blocks until an item is present (returns the oldest) or the slot is closed (nothing).
  std::optional<T> Take() {
    std::unique_lock<std::mutex> lock(mutex_);
    ready_.wait(lock, [this] { return closed_ || !items_.empty(); });
    if (closed_) return std::nullopt;
    std::optional<T> out = std::move(items_.front());
    items_.pop_front();
    return out;
  }

  /// Wakes Take() for good; later Put() calls are still accepted but never taken.
  void Close() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      closed_ = true;
    }
    ready_.notify_all();
  }

  /// Items dropped before being taken.
  uint64_t dropped() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return dropped_;
  }

 private:
  const size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<T> items_;
  bool closed_ = false;
  uint64_t dropped_ = 0;
};

}  // namespace ros_layer
}  // namespace dslam
