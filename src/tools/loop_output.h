#pragma once
// dslam_run_dataset --loop-closing / --loops: loop closing over the run's keyframe map
// (LoopClosing, part loop_closing, one of Slam's keyframe observers) and its outputs: the loop
// file (io/loop_io.h: the query keyframe's camera in the matched keyframe's, as verified), the
// loop count and the loop work's time per keyframe in the summary.

#include <memory>
#include <string>
#include <vector>

#include "dslam/backend/slam.h"
#include "dslam/core/config.h"
#include "dslam/eval/json_writer.h"
#include "dslam/loop_closing/loop_closing.h"

namespace dslam {
namespace tools {

/// Loop closing when config.loop_closing.enabled and config.backend.enabled (it works on the
/// back end's keyframe map).
class LoopOutput {
 public:
  /// Loop closing with `vocabulary` when it is on, its keyframes processed as `mode` says
  /// (LoopClosing). Throws std::invalid_argument when it is on and `vocabulary` is null.
  LoopOutput(const Config& config, std::shared_ptr<const Vocabulary> vocabulary, WorkerMode mode);

  /// The loop closer, for Slam's constructor (empty when off).
  std::vector<std::shared_ptr<KeyFrameObserver>> Observers() const;
  /// Gives the loop closer the Slam it corrects; call before the first frame.
  void Attach(Slam* slam);
  bool enabled() const { return closer_ != nullptr; }  ///< loop closing runs
  /// Returns when loop closing processed every keyframe; call after Slam::WaitForBackEnd, and
  /// Slam::WaitForBackEnd again after it so that the last correction reaches the observers.
  void Wait();
  /// Loop closing's errors (LoopClosing::errors); null when it is off.
  std::shared_ptr<ErrorLog> errors() const { return closer_ ? closer_->errors() : nullptr; }

  /// Writes the accepted loops to `path` (loop_io.h) when not empty; call after Wait.
  void Write(const std::string& path) const;
  /// One line: loops closed, time per keyframe.
  void Print() const;
  /// Adds loop_closing, loop_closures, median_loop_ms and p95_loop_ms.
  void AddTo(JsonObject* json) const;

 private:
  std::shared_ptr<LoopClosing> closer_;
};

}  // namespace tools
}  // namespace dslam
