// dslam_run_dataset's progress on stderr (run_progress.h).
#include "run_progress.h"

#include <unistd.h>

#include <cstdio>

namespace dslam {
namespace tools {

void Progress(size_t done, size_t total, const FrameResult& r) {
  static const bool terminal = isatty(fileno(stderr));
  if (!terminal) {
    if (done * 10 / total != (done - 1) * 10 / total || done == total) {
      std::fprintf(stderr, "%3zu%% %zu/%zu frames\n", done * 100 / total, done, total);
    }
    return;
  }
  const int width = 30;
  const int filled = static_cast<int>(width * done / total);
  std::fprintf(stderr, "\r[%s%s] %zu/%zu %-11s %5.1f ms", std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), done, total, ToString(r.state),
               r.times.total_ms);
}

void FrameMessages::Add(const FrameResult& r) {
  if (r.message == last_) {
    repeats_ += !r.message.empty();
    return;
  }
  Flush();
  last_ = r.message;
  if (last_.empty()) return;
  static const bool terminal = isatty(fileno(stderr));
  std::fprintf(stderr, "%sframe %d (%.3f): %s: %s\n", terminal ? "\n" : "", r.frame_index,
               r.stamp_s, ToString(r.state), r.message.c_str());
}

void FrameMessages::Flush() {
  if (repeats_ > 0) std::fprintf(stderr, "  and %d more frames with that message\n", repeats_);
  repeats_ = 0;
}

}  // namespace tools
}  // namespace dslam
