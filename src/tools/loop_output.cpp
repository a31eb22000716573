#include "loop_output.h"

#include <cstdio>

#include "dslam/eval/quantile.h"
#include "dslam/io/loop_io.h"
#include "dslam/place_recognition/vocabulary.h"

namespace dslam {
namespace tools {

LoopOutput::LoopOutput(const Config& config, std::shared_ptr<const Vocabulary> vocabulary,
                       WorkerMode mode) {
  if (!config.loop_closing.enabled || !config.backend.enabled) return;
  closer_ = std::make_shared<LoopClosing>(config, std::move(vocabulary), mode);
}

void LoopOutput::Wait() {
  if (closer_) closer_->Wait();
}

std::vector<std::shared_ptr<KeyFrameObserver>> LoopOutput::Observers() const {
  if (!closer_) return {};
  return {closer_};
}

void LoopOutput::Attach(Slam* slam) {
  if (closer_) closer_->Attach(slam);
}

void LoopOutput::Write(const std::string& path) const {
  if (path.empty()) return;
  std::vector<LoopRecord> records;
  if (closer_) {
    for (const ClosedLoop& loop : closer_->loops()) {
      LoopRecord record;
      record.stamp_query_s = loop.detection.query_stamp_s;
      record.stamp_match_s = loop.detection.match_stamp_s;
      record.T_match_query = loop.detection.T_match_query;
      records.push_back(record);
    }
  }
  WriteLoopFile(path, records);
}

void LoopOutput::Print() const {
  if (!closer_) return;
  const std::vector<double> times = closer_->times_ms();
  const std::vector<ClosedLoop> loops = closer_->loops();
  std::printf("loop closing: %zu loops closed, median %.2f ms per keyframe (p95 %.2f)\n",
              loops.size(), Median(times), Quantile(times, 0.95));
  for (const ClosedLoop& loop : loops) {
    std::printf(
        "  loop: frame %d seen again at frame %d, %d inliers; query keyframe moved %.3f m, "
        "%.2f deg\n",
        loop.detection.match_frame_index, loop.detection.query_frame_index, loop.detection.inliers,
        loop.query_moved_m, loop.query_turned_deg);
  }
}

void LoopOutput::AddTo(JsonObject* json) const {
  json->AddBool("loop_closing", enabled());
  if (!closer_) return;
  const std::vector<double> times = closer_->times_ms();
  json->AddInteger("loop_closures", static_cast<int>(closer_->loops().size()))
      .AddNumber("median_loop_ms", Median(times), 6)
      .AddNumber("p95_loop_ms", Quantile(times, 0.95), 6);
}

}  // namespace tools
}  // namespace dslam
