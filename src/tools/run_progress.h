#pragma once
// dslam_run_dataset's progress on stderr: the progress bar and the frames that carry a message.

#include <cstddef>
#include <string>

#include "dslam/tracking/frame_result.h"

namespace dslam {
namespace tools {

/// A bar redrawn in place on a terminal; one line per 10% otherwise (logs stay readable).
/// `done` frames of `total` (>= 1), `r` the last one's result.
void Progress(size_t done, size_t total, const FrameResult& r);

/// Prints the frames that carry a message (lost, reset, re-initialised, relocalised) to stderr,
/// once per run of frames with the same message, e.g.
/// "frame 1 (1305031229.564): lost: too few pose inliers".
class FrameMessages {
 public:
  /// Prints `r`'s message when it differs from the previous frame's, else counts a repeat.
  void Add(const FrameResult& r);
  /// Prints how many frames repeated the last message.
  void Flush();

 private:
  std::string last_;
  int repeats_ = 0;
};

}  // namespace tools
}  // namespace dslam
