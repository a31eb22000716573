#pragma once
// Fork-join of two independent steps on OpenCV's thread pool: steps of Odometry::ProcessFrame
// (e.g. the motion-only pose beside the Delaunay graph) and MovingObjectTracker's dynamic mask
// beside its optical flow.

#include <exception>

#include <opencv2/core/utility.hpp>

namespace dslam {

/// Runs `first` and `second` in parallel on OpenCV's thread pool (one after the other with one
/// thread) and returns when both are done; an exception of either is rethrown here.
template <typename First, typename Second>
void RunSideBySide(First&& first, Second&& second) {
  std::exception_ptr errors[2];
  cv::parallel_for_(cv::Range(0, 2), [&](const cv::Range& range) {
    for (int task = range.start; task < range.end; ++task) {
      try {
        task == 0 ? first() : second();
      } catch (...) {
        errors[task] = std::current_exception();
      }
    }
  });
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace dslam
