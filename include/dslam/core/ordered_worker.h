#pragma once
// A single worker that runs posted tasks one at a time, in the order they were posted: on a
// thread of its own (threaded) or inside Post (synchronous). The moving objects use it to run
// beside the tracking thread (ObjectsOutput, ObjectsPublisher): every frame's objects depend on
// the frames before them, so they must see the frames in order, but not on the tracking thread.
//
// Locking policy: one mutex guards the queue, the busy flag, the stop flag and a stored error;
// tasks run without it, on the worker thread only, so whatever a task touches is the worker
// thread's alone while tasks run. Post and Wait are for one thread (the poster).

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace dslam {

/// Where OrderedWorker runs its tasks.
enum class WorkerMode {
  kSynchronous,  ///< inside Post, on the poster's thread (deterministic timing too)
  kThreaded,     ///< on the worker's own thread, beside the poster
};

/// Runs tasks in posting order on one thread (locking policy above).
class OrderedWorker {
 public:
  /// Starts the worker thread in WorkerMode::kThreaded. Post blocks while `max_pending` tasks
  /// wait, so the queue and the memory the tasks capture stay bounded. Throws
  /// std::invalid_argument when max_pending < 1.
  OrderedWorker(WorkerMode mode, int max_pending);

  /// Runs the tasks still queued, then stops the thread. A task's error is not rethrown here.
  ~OrderedWorker();

  OrderedWorker(const OrderedWorker&) = delete;
  OrderedWorker& operator=(const OrderedWorker&) = delete;

  /// Queues `task` (synchronous: runs it now). Blocks while max_pending tasks wait. Rethrows the
  /// first exception a task threw since the last Post or Wait (that task's successors still ran).
  void Post(std::function<void()> task);

  /// Returns when every posted task has run; rethrows as Post does.
  void Wait();

  /// Tasks posted and not yet finished (threaded; 0 in synchronous mode between calls).
  int Pending() const;

 private:
  void Run();  ///< the worker thread's loop
  void RethrowLocked(std::unique_lock<std::mutex>& lock);

  const WorkerMode mode_;
  const int max_pending_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;  ///< queue, busy_ or stop_ changed
  std::deque<std::function<void()>> queue_;
  bool busy_ = false;  ///< a task is running on the worker thread
  bool stop_ = false;
  std::exception_ptr error_;  ///< first error of a task since the last rethrow
  std::thread thread_;        ///< started last (members above initialised before it runs)
};

}  // namespace dslam
