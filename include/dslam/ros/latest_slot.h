#pragma once
// A one-slot mailbox between the subscriber callback and the processing thread: Put() never
// blocks and replaces an unprocessed item (counted as dropped); Take() blocks until an item
// arrives or Close() is called. Keeps the callback short whatever the processing time.

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <utility>

namespace dslam {
namespace ros_layer {

template <typename T>
class LatestSlot {
 public:
  /// Stores `item`, replacing an unprocessed one; returns true when one was replaced (dropped).
  bool Put(T item) {
    bool replaced = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      replaced = item_.has_value();
      item_ = std::move(item);
      dropped_ += replaced;
    }
    ready_.notify_one();
    return replaced;
  }

  /// Blocks until an item is present (returns it) or the slot is closed (returns nothing).
  std::optional<T> Take() {
    std::unique_lock<std::mutex> lock(mutex_);
    ready_.wait(lock, [this] { return closed_ || item_.has_value(); });
    if (closed_) return std::nullopt;
    std::optional<T> out = std::move(item_);
    item_.reset();
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

  /// Items replaced before being taken.
  uint64_t dropped() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return dropped_;
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::optional<T> item_;
  bool closed_ = false;
  uint64_t dropped_ = 0;
};

}  // namespace ros_layer
}  // namespace dslam
