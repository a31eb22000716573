#pragma once
// A unique lock that measures how long its mutex is held: Slam's map lock, so that the longest
// hold (what tracking may have to wait for) can be reported while a run goes on.

#include <chrono>
#include <mutex>

namespace dslam {

/// The longest hold of a mutex measured so far.
struct LockHold {
  double ms = 0.0;               ///< [ms] from acquiring to releasing
  const char* where = "(none)";  ///< the holder (a string literal)
};

/// Locks `mutex` on construction, unlocks on destruction, and records each hold (lock to unlock)
/// into `longest` when it is the longest so far. `longest` is written while `mutex` is held, so
/// the mutex guards it. Meets BasicLockable: a std::condition_variable_any releases it while it
/// waits, and the wait does not count as a hold.
class TimedLock {
 public:
  TimedLock(std::mutex& mutex, LockHold* longest, const char* where)
      : mutex_(mutex), longest_(longest), where_(where) {
    lock();
  }
  ~TimedLock() {
    if (owns_) unlock();
  }
  TimedLock(const TimedLock&) = delete;
  TimedLock& operator=(const TimedLock&) = delete;

  void lock() {
    mutex_.lock();
    owns_ = true;
    since_ = std::chrono::steady_clock::now();
  }
  void unlock() {
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since_)
            .count();
    if (ms > longest_->ms) *longest_ = {ms, where_};
    owns_ = false;
    mutex_.unlock();
  }
  bool owns_lock() const { return owns_; }

 private:
  std::mutex& mutex_;
  LockHold* longest_;
  const char* where_;
  bool owns_ = false;
  std::chrono::steady_clock::time_point since_;
};

}  // namespace dslam
