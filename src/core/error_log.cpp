#include "dslam/core/error_log.h"

#include <exception>
#include <utility>

namespace dslam {

ErrorLog::ErrorLog(size_t max_kept) : max_kept_(max_kept < 1 ? 1 : max_kept) {}

void ErrorLog::Report(const std::string& where, const std::string& what) {
  const std::lock_guard<std::mutex> lock(mutex_);
  ++count_;
  if (untaken_.size() >= max_kept_) untaken_.erase(untaken_.begin());
  untaken_.push_back({where, what});
}

bool ErrorLog::Run(const std::string& where, const std::function<void()>& work) {
  try {
    work();
    return true;
  } catch (const std::exception& e) {
    Report(where, e.what());
  } catch (...) {
    Report(where, "unknown exception");
  }
  return false;
}

int64_t ErrorLog::count() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return count_;
}

std::vector<ReportedError> ErrorLog::TakeNew() {
  const std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(untaken_, {});
}

}  // namespace dslam
