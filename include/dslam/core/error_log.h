#pragma once
// Errors of work that runs where no caller can catch them: a keyframe observer called by Slam, a
// task of an OrderedWorker, a back-end run, a loop whose correction failed. Each error is
// reported once, where it happened, and counted; the work after it goes on. Whoever shows
// errors (the node's log and status, the offline runner's stderr and summary) takes the new
// ones from the log.
//
// Locking policy: one mutex guards the count and the kept messages; Report and the getters take
// it only for the copy, so any thread may call any member.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace dslam {

/// One reported error.
struct ReportedError {
  std::string where;  ///< the part that failed, e.g. "loop closing"
  std::string what;   ///< the exception's message
};

/// Counts errors and keeps the newest messages until they are taken (locking policy above).
class ErrorLog {
 public:
  /// At most `max_kept` untaken messages are kept (the oldest are dropped, still counted), so a
  /// fault that repeats every frame keeps memory bounded.
  explicit ErrorLog(size_t max_kept = 32);

  /// Counts an error of `where` and keeps its message for TakeNew.
  void Report(const std::string& where, const std::string& what);

  /// Runs `work`; an exception it throws is reported as an error of `where` (its what(), or
  /// "unknown exception") instead of leaving this call. Returns whether `work` finished.
  bool Run(const std::string& where, const std::function<void()>& work);

  /// Errors reported since construction, taken or not.
  int64_t count() const;

  /// The messages reported since the last call, oldest first (at most max_kept).
  std::vector<ReportedError> TakeNew();

 private:
  const size_t max_kept_;
  mutable std::mutex mutex_;
  int64_t count_ = 0;
  std::vector<ReportedError> untaken_;
};

}  // namespace dslam
