#include "dslam/ros/input_checks.h"

#include <cstdio>

namespace dslam {
namespace ros_layer {

StampVerdict StampCheck::Check(double stamp_s) {
  StampVerdict verdict;
  char text[160];
  if (stamp_s == 0.0) {
    verdict.accept = false;
    verdict.problem = "zero timestamp (the driver sets no stamps): frame skipped";
    return verdict;
  }
  if (have_last_ && stamp_s == last_s_) {
    verdict.accept = false;
    std::snprintf(text, sizeof(text),
                  "repeated timestamp %.6f (a duplicated message): frame skipped", stamp_s);
    verdict.problem = text;
    return verdict;
  }
  if (have_last_ && stamp_s < last_s_) {
    verdict.backwards = true;
    std::snprintf(text, sizeof(text),
                  "time went backwards by %.3f s: the odometry starts a new run (at the origin, "
                  "or in the loaded keyframe map) and the saved trajectory a new segment",
                  last_s_ - stamp_s);
    verdict.problem = text;
  } else if (have_last_ && stamp_s - last_s_ > gap_warning_s_) {
    std::snprintf(text, sizeof(text),
                  "%.3f s since the previous frame: tracking resumes from the last pose",
                  stamp_s - last_s_);
    verdict.problem = text;
  }
  have_last_ = true;
  last_s_ = stamp_s;
  return verdict;
}

void InputWatchdog::Arrived(Input input, double stamp_s) {
  ++arrived_[input];
  last_stamp_s_[input] = stamp_s;
}

std::string InputWatchdog::Check() {
  std::string warning;
  const bool any = arrived_[0] + arrived_[1] + arrived_[2] > 0;
  if (sets_ == 0 && any) {
    std::string missing;
    for (int i = 0; i < 3; ++i) {
      if (arrived_[i] == 0) missing += (missing.empty() ? "" : ", ") + names_[i];
    }
    if (!missing.empty()) {
      warning = "images arrive but nothing on " + missing + ": no frame can be processed";
    } else {
      char text[256];
      std::snprintf(text, sizeof(text),
                    "all inputs arrive but their stamps never match (last colour %.6f, depth "
                    "%.6f, camera_info %.6f): no frame can be processed",
                    last_stamp_s_[0], last_stamp_s_[1], last_stamp_s_[2]);
      warning = text;
    }
  }
  arrived_.fill(0);
  sets_ = 0;
  return warning;
}

}  // namespace ros_layer
}  // namespace dslam
