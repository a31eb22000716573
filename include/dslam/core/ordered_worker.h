#pragma once
// A single worker that runs posted tasks one at a time, in the order they were posted: on a
// thread of its own (threaded) or inside Post (synchronous). The moving objects use it to run
// beside the tracking thread (ObjectsOutput, ObjectsPublisher): every frame's objects depend on
// the frames before them, so they must see the frames in order, but not on the tracking thread.
//
// A task's exception is reported to the worker's ErrorLog (counted, with its message) where it
// happened, and the tasks after it run: it is never rethrown into the poster, whose own work
// (another observer, the next frame) has nothing to do with it.
//
// Locking policy: one mutex guards the queue, the busy flag and the stop flag; tasks run without
// it, on the worker thread only, so whatever a task touches is the worker thread's alone while
// tasks run. Post and Wait are for one thread (the poster). The ErrorLog has its own lock.

#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "dslam/core/error_log.h"

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
  /// wait, so the queue and the memory the tasks capture stay bounded. A task's exception goes
  /// to `errors` (a log of its own when null) as an error of `where`. Throws
  /// std::invalid_argument when max_pending < 1.
  OrderedWorker(WorkerMode mode, int max_pending, std::shared_ptr<ErrorLog> errors = nullptr,
                std::string where = "worker");

  /// Runs the tasks still queued, then stops the thread.
  ~OrderedWorker();

  OrderedWorker(const OrderedWorker&) = delete;
  OrderedWorker& operator=(const OrderedWorker&) = delete;

  /// Queues `task` (synchronous: runs it now). Blocks while max_pending tasks wait. Never
  /// throws the task's exception (it goes to errors()).
  void Post(std::function<void()> task);

  /// Returns when every posted task has run.
  void Wait();

  /// Where the tasks' exceptions are reported (shared with whoever was given it).
  ErrorLog& errors() const { return *errors_; }

  /// Tasks posted and not yet finished (threaded; 0 in synchronous mode between calls).
  int Pending() const;

 private:
  void Run();  ///< the worker thread's loop

  const WorkerMode mode_;
  const int max_pending_;
  const std::shared_ptr<ErrorLog> errors_;
  const std::string where_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;  ///< queue, busy_ or stop_ changed
  std::deque<std::function<void()>> queue_;
  bool busy_ = false;  ///< a task is running on the worker thread
  bool stop_ = false;
  std::thread thread_;  ///< started last (members above initialised before it runs)
};

}  // namespace dslam
