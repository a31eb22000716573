#pragma once
// Wall-clock stopwatch for per-stage timings.

#include <chrono>

namespace dslam {

/// Starts at construction; ElapsedMs() reads without stopping.
class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}

  /// [ms] since construction or the last Restart().
  double ElapsedMs() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
        .count();
  }

  /// Returns ElapsedMs() and starts again.
  double Restart() {
    const double ms = ElapsedMs();
    start_ = std::chrono::steady_clock::now();
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace dslam
