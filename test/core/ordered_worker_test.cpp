// OrderedWorker: tasks in posting order on one thread, bounded queue, errors handed back.
#include <atomic>
#include <chrono>
#include <future>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/core/ordered_worker.h"

namespace dslam {
namespace {

TEST(OrderedWorker, ThreadedRunsTasksInPostingOrderOnItsOwnThread) {
  std::vector<int> order;  // touched only by the worker thread until Wait returns
  std::vector<std::thread::id> threads;
  OrderedWorker worker(WorkerMode::kThreaded, 3);
  for (int i = 0; i < 200; ++i) {
    worker.Post([&order, &threads, i] {
      order.push_back(i);
      threads.push_back(std::this_thread::get_id());
    });
  }
  worker.Wait();
  ASSERT_EQ(order.size(), 200u);
  for (int i = 0; i < 200; ++i) EXPECT_EQ(order[i], i);
  for (const std::thread::id& id : threads) {
    EXPECT_EQ(id, threads.front());
    EXPECT_NE(id, std::this_thread::get_id());
  }
  EXPECT_EQ(worker.Pending(), 0);
}

TEST(OrderedWorker, SynchronousRunsEachTaskInsidePost) {
  OrderedWorker worker(WorkerMode::kSynchronous, 1);
  std::thread::id ran_on;
  int runs = 0;
  worker.Post([&] {
    ran_on = std::this_thread::get_id();
    ++runs;
  });
  EXPECT_EQ(runs, 1);  // before Wait
  EXPECT_EQ(ran_on, std::this_thread::get_id());
  EXPECT_THROW(worker.Post([] { throw std::runtime_error("task failed"); }), std::runtime_error);
}

TEST(OrderedWorker, PostBlocksWhileMaxPendingTasksWait) {
  std::promise<void> gate;
  std::shared_future<void> open = gate.get_future().share();
  OrderedWorker worker(WorkerMode::kThreaded, 2);
  worker.Post([open] { open.wait(); });  // runs and blocks the worker
  while (worker.Pending() != 1) std::this_thread::yield();
  worker.Post([] {});
  worker.Post([] {});  // two tasks wait now: the queue is full
  std::atomic<bool> posted{false};
  std::thread poster([&] {
    worker.Post([] {});
    posted = true;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_FALSE(posted.load());
  EXPECT_EQ(worker.Pending(), 3);
  gate.set_value();
  poster.join();
  EXPECT_TRUE(posted.load());
  worker.Wait();
  EXPECT_EQ(worker.Pending(), 0);
}

TEST(OrderedWorker, TaskErrorIsRethrownOnceAndLaterTasksStillRun) {
  std::promise<void> gate;
  std::shared_future<void> open = gate.get_future().share();
  OrderedWorker worker(WorkerMode::kThreaded, 4);
  int after = 0;
  worker.Post([open] { open.wait(); });  // nothing fails before the last Post
  worker.Post([] { throw std::runtime_error("first"); });
  worker.Post([] { throw std::runtime_error("second"); });
  worker.Post([&after] { ++after; });
  gate.set_value();
  try {
    worker.Wait();
    FAIL() << "Wait did not rethrow";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "first");
  }
  EXPECT_EQ(after, 1);
  EXPECT_NO_THROW(worker.Wait());  // handed back once
}

TEST(OrderedWorker, TaskErrorIsRethrownByTheNextPostWhoseTaskStillRuns) {
  OrderedWorker worker(WorkerMode::kThreaded, 2);
  worker.Post([] { throw std::runtime_error("failed"); });
  while (worker.Pending() != 0) std::this_thread::yield();  // the failing task has run
  std::atomic<bool> ran{false};
  EXPECT_THROW(worker.Post([&ran] { ran = true; }), std::runtime_error);
  EXPECT_NO_THROW(worker.Wait());  // handed back once
  EXPECT_TRUE(ran.load());         // queued before the error was handed back
}

TEST(OrderedWorker, DestructorRunsTheQueuedTasks) {
  std::atomic<int> runs{0};
  {
    OrderedWorker worker(WorkerMode::kThreaded, 8);
    for (int i = 0; i < 8; ++i) {
      worker.Post([&runs] {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        ++runs;
      });
    }
  }
  EXPECT_EQ(runs.load(), 8);
}

TEST(OrderedWorker, MaxPendingBelowOneIsRejected) {
  EXPECT_THROW(OrderedWorker(WorkerMode::kThreaded, 0), std::invalid_argument);
}

}  // namespace
}  // namespace dslam
