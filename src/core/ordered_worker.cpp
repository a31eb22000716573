#include "dslam/core/ordered_worker.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace dslam {

OrderedWorker::OrderedWorker(WorkerMode mode, int max_pending, std::shared_ptr<ErrorLog> errors,
                             std::string where)
    : mode_(mode),
      max_pending_(max_pending),
      errors_(errors ? std::move(errors) : std::make_shared<ErrorLog>()),
      where_(std::move(where)) {
  if (max_pending < 1) {
    throw std::invalid_argument("OrderedWorker: max_pending must be >= 1, is " +
                                std::to_string(max_pending));
  }
  if (mode_ == WorkerMode::kThreaded) thread_ = std::thread([this] { Run(); });
}

OrderedWorker::~OrderedWorker() {
  if (!thread_.joinable()) return;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void OrderedWorker::Post(std::function<void()> task) {
  if (mode_ == WorkerMode::kSynchronous) {
    errors_->Run(where_, task);
    return;
  }
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return static_cast<int>(queue_.size()) < max_pending_; });
  queue_.push_back(std::move(task));
  changed_.notify_all();
}

void OrderedWorker::Wait() {
  if (mode_ == WorkerMode::kSynchronous) return;
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return queue_.empty() && !busy_; });
}

int OrderedWorker::Pending() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<int>(queue_.size()) + (busy_ ? 1 : 0);
}

void OrderedWorker::Run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    changed_.wait(lock, [this] { return stop_ || !queue_.empty(); });
    if (queue_.empty()) return;  // stopped, nothing left to run
    std::function<void()> task = std::move(queue_.front());
    queue_.pop_front();
    busy_ = true;
    changed_.notify_all();  // a slot is free for Post
    lock.unlock();
    errors_->Run(where_, task);
    lock.lock();
    busy_ = false;
    changed_.notify_all();
  }
}

}  // namespace dslam
