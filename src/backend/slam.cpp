#include "dslam/backend/slam.h"

#include <stdexcept>
#include <utility>

#include "dslam/backend/window_static_points.h"
#include "dslam/core/stopwatch.h"

namespace dslam {

Slam::Slam(const Config& config, BackEndMode mode, RefinedPosesRecording refined)
    : mode_(mode), refined_recording_(refined), odometry_(config) {
  if (mode_ == BackEndMode::kThreaded) back_end_ = std::thread(&Slam::BackEndLoop, this);
}

FrameResult Slam::ProcessFrame(const RgbdFrame& frame) {
  const Stopwatch tracking;  // this thread's time: waiting for the lock, front end, bookkeeping
  const Lock lock(map_mutex_);
  RethrowBackEndError();
  // Front end (Sec. V-A, V-B): features, local-map matching, pose from static points, front-end
  // static point determination, map management and keyframes.
  FrameResult result = odometry_.ProcessFrame(frame);
  if (result.has_pose && refined_recording_ == RefinedPosesRecording::kOn) {
    refined_.AddFrame(result.stamp_s, result.T_world_camera, map());
  }
  if (mode_ == BackEndMode::kThreaded) ExchangeWithBackEnd(&result);
  result.times.tracking_ms = tracking.ElapsedMs();
  // Back end (Sec. V): local mapping on the window the new keyframe completes.
  if (mode_ == BackEndMode::kSynchronous && result.keyframe && config().backend.enabled) {
    result.backend = RunLocalMapping();
  }
  return result;
}

BackEndStatus Slam::RunLocalMapping() {
  BackEndStatus status;
  // Algorithm 1 over the window first: local BA then uses only the points that stayed marked.
  if (config().backend.spd_enabled && config().static_points.enabled) {
    const WindowStaticPointsStats spd =
        DetermineStaticPointsInWindow(config(), odometry_.mutable_map());
    status.spd_ran = spd.ran;
    status.spd_keyframes = spd.keyframes;
    status.spd_points = spd.points;
    status.spd_edges = spd.edges;
    status.spd_culled_edges = spd.culled_edges;
    status.spd_unmarked = spd.unmarked;
    status.spd_graph_ms = spd.graph_ms;
    status.spd_culling_ms = spd.culling_ms;
    status.spd_components_ms = spd.components_ms;
    status.spd_ms = spd.total_ms;
  }
  const LocalBaStats ba = LocalBundleAdjustment(config().backend, odometry_.mutable_map());
  // Tracking goes on from the refined pose of the keyframe just made (this frame).
  if (ba.ran && !ba.rejected) {
    odometry_.AdoptNewestKeyFramePose();
    if (refined_recording_ == RefinedPosesRecording::kOn) refined_.UpdateKeyFrames(map());
  }
  status.ran = ba.ran;
  status.window_keyframes = static_cast<int>(map().keyframes().size());
  status.ba_keyframes = ba.keyframes;
  status.ba_points = ba.points;
  status.ba_measurements = ba.measurements;
  status.ba_outliers = ba.outliers;
  status.ba_iterations = ba.iterations;
  status.ba_rejected = ba.rejected;
  status.ba_ms = ba.time_ms;
  return status;
}

Slam::~Slam() {
  if (!back_end_.joinable()) return;
  {
    const Lock lock(map_mutex_);  // a run in progress holds it: this waits for its end
    stop_ = true;
  }
  work_.notify_all();
  back_end_.join();
}

void Slam::BackEndLoop() {
  Lock lock(map_mutex_);
  for (;;) {
    work_.wait(lock, [this] { return stop_ || (pending_ > 0 && !held_); });
    if (stop_) return;  // queued keyframes are dropped
    pending_ = 0;       // one run for all of them: the window of the newest keyframe
    try {
      completed_.push_back(RunLocalMapping());
    } catch (...) {
      error_ = std::current_exception();
    }
    idle_.notify_all();
  }
}

void Slam::ExchangeWithBackEnd(FrameResult* result) {
  BackEndThreadStatus& thread = result->backend_thread;
  thread.threaded = true;
  if (result->keyframe && config().backend.enabled) {
    ++pending_;
    work_.notify_one();  // the back-end thread starts when this thread releases the lock
  }
  if (!completed_.empty()) {
    result->backend = completed_.front();
    completed_.pop_front();
    thread.delivered = true;
  }
  thread.backlog = pending_;
}

void Slam::RethrowBackEndError() {
  if (!error_) return;
  const std::exception_ptr error = std::exchange(error_, nullptr);
  std::rethrow_exception(error);
}

void Slam::Reset() {
  const Lock lock(map_mutex_);  // waits for a run in progress
  pending_ = 0;
  completed_.clear();
  odometry_.Reset();
}

void Slam::WaitForBackEnd() {
  Lock lock(map_mutex_);
  if (held_) {
    held_ = false;
    work_.notify_all();
  }
  idle_.wait(lock, [this] { return pending_ == 0; });  // the lock held: no run in progress
  RethrowBackEndError();
}

std::vector<BackEndStatus> Slam::TakeUnreportedRuns() {
  const Lock lock(map_mutex_);
  std::vector<BackEndStatus> runs(completed_.begin(), completed_.end());
  completed_.clear();
  return runs;
}

void Slam::HoldBackEnd(bool hold) {
  {
    const Lock lock(map_mutex_);
    held_ = hold && mode_ == BackEndMode::kThreaded;
  }
  work_.notify_all();
}

Trajectory Slam::RefinedPoses() const {
  if (refined_recording_ != RefinedPosesRecording::kOn) {
    throw std::logic_error("Slam::RefinedPoses: not recorded (RefinedPosesRecording::kOff)");
  }
  const Lock lock(map_mutex_);
  return refined_.Poses();
}

Map Slam::MapSnapshot() const {
  const Lock lock(map_mutex_);
  return map();
}

}  // namespace dslam
