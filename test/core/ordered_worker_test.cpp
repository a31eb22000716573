// OrderedWorker: tasks in posting order on one thread, bounded queue, errors reported to its
// ErrorLog and never thrown into the poster.
#include <atomic>
#include <chrono>
#include <future>
#include <stdexcept>
#include <string>
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
  EXPECT_NO_THROW(worker.Post([] { throw std::runtime_error("task failed"); }));
  EXPECT_EQ(worker.errors().count(), 1);
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

TEST(OrderedWorker, TaskErrorsAreReportedWhereTheyHappenedAndLaterTasksStillRun) {
  std::promise<void> gate;
  std::shared_future<void> open = gate.get_future().share();
  auto errors = std::make_shared<ErrorLog>();
  OrderedWorker worker(WorkerMode::kThreaded, 4, errors, "loop closing");
  int after = 0;
  worker.Post([open] { open.wait(); });
  worker.Post([] { throw std::runtime_error("first"); });
  worker.Post([] { throw std::runtime_error("second"); });
  worker.Post([&after] { ++after; });
  gate.set_value();
  EXPECT_NO_THROW(worker.Wait());  // never handed to the poster
  EXPECT_EQ(after, 1);
  EXPECT_EQ(errors->count(), 2);
  const std::vector<ReportedError> taken = errors->TakeNew();
  ASSERT_EQ(taken.size(), 2u);
  EXPECT_EQ(taken[0].where, "loop closing");
  EXPECT_EQ(taken[0].what, "first");
  EXPECT_EQ(taken[1].what, "second");
  EXPECT_TRUE(errors->TakeNew().empty());  // reported once
}

TEST(OrderedWorker, APostAfterAFailedTaskDoesNotThrow) {
  OrderedWorker worker(WorkerMode::kThreaded, 2);
  worker.Post([] { throw std::runtime_error("failed"); });
  while (worker.Pending() != 0) std::this_thread::yield();  // the failing task has run
  std::atomic<bool> ran{false};
  EXPECT_NO_THROW(worker.Post([&ran] { ran = true; }));
  worker.Wait();
  EXPECT_TRUE(ran.load());
  EXPECT_EQ(worker.errors().count(), 1);
}

TEST(ErrorLog, RunReportsAnyExceptionAndSaysWhetherTheWorkFinished) {
  ErrorLog log;
  int ran = 0;
  EXPECT_TRUE(log.Run("a", [&] { ++ran; }));
  EXPECT_FALSE(log.Run("b", [] { throw std::runtime_error("failed"); }));
  EXPECT_FALSE(log.Run("c", [] { throw 42; }));  // not a std::exception
  EXPECT_EQ(ran, 1);
  const std::vector<ReportedError> taken = log.TakeNew();
  ASSERT_EQ(taken.size(), 2u);
  EXPECT_EQ(taken[0].where, "b");
  EXPECT_EQ(taken[0].what, "failed");
  EXPECT_EQ(taken[1].where, "c");
  EXPECT_EQ(taken[1].what, "unknown exception");
}

TEST(ErrorLog, KeepsTheNewestMessagesAndCountsAll) {
  ErrorLog log(2);
  for (int i = 0; i < 5; ++i) log.Report("x", std::to_string(i));
  EXPECT_EQ(log.count(), 5);
  const std::vector<ReportedError> taken = log.TakeNew();
  ASSERT_EQ(taken.size(), 2u);
  EXPECT_EQ(taken[0].what, "3");
  EXPECT_EQ(taken[1].what, "4");
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
