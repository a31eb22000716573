#include "dslam/backend/slam.h"

#include <utility>

#include "dslam/core/stopwatch.h"

namespace dslam {

Slam::Slam(const Config& config, BackEndMode mode, RefinedPoseRecording refined)
    : mode_(mode), refined_recording_(refined), odometry_(config) {
  if (mode_ == BackEndMode::kThreaded) back_end_ = std::thread(&Slam::BackEndLoop, this);
}

FrameResult Slam::ProcessFrame(const RgbdFrame& frame, const FrameRequest& request) {
  const Stopwatch tracking;  // this thread's time: waiting for the lock, front end, bookkeeping
  const Lock lock(map_mutex_);
  RethrowBackEndError();
  // Front end (Sec. V-A, V-B): features, local-map matching, pose from static points, front-end
  // static point determination, map management and keyframes.
  FrameResult result = odometry_.ProcessFrame(frame, request);
  if (result.reset) DropBackEndWork();  // the old world's keyframes and runs
  if (result.has_pose && refined_recording_ == RefinedPoseRecording::kOn) {
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
  LocalMappingJob job(map(), generation_);
  job.Run(config());
  return FinishLocalMapping(job);
}

BackEndStatus Slam::FinishLocalMapping(const LocalMappingJob& job) {
  job.Apply(odometry_.mutable_map());
  // Tracking goes on from the refined pose of the keyframe just made (this frame).
  if (job.moved_keyframes()) {
    odometry_.AdoptNewestKeyFramePose();
    if (refined_recording_ == RefinedPoseRecording::kOn) refined_.UpdateKeyFrames(map());
  }
  BackEndStatus status = job.status();
  status.window_keyframes = static_cast<int>(map().keyframes().size());
  return status;
}

Slam::~Slam() {
  if (!back_end_.joinable()) return;
  {
    const Lock lock(map_mutex_);
    stop_ = true;  // a job in progress finishes, then the thread ends
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
    running_ = true;
    try {
      LocalMappingJob job(map(), generation_);
      lock.unlock();  // tracking goes on while the job works on its copy
      job.Run(config());
      lock.lock();
      if (job.generation() == generation_) completed_.push_back(FinishLocalMapping(job));
    } catch (...) {
      if (!lock.owns_lock()) lock.lock();
      error_ = std::current_exception();
    }
    running_ = false;
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

void Slam::Reset(ResetMode mode) {
  const Lock lock(map_mutex_);
  DropBackEndWork();
  odometry_.Reset(mode);
}

void Slam::DropBackEndWork() {
  pending_ = 0;
  completed_.clear();
  ++generation_;  // a job in progress belongs to the old map
}

void Slam::WaitForBackEnd() {
  Lock lock(map_mutex_);
  if (held_) {
    held_ = false;
    work_.notify_all();
  }
  idle_.wait(lock, [this] { return pending_ == 0 && !running_; });
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
  const Lock lock(map_mutex_);
  return refined_.Poses();
}

Map Slam::MapSnapshot() const {
  const Lock lock(map_mutex_);
  return map();
}

}  // namespace dslam
