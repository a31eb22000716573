#include "dslam/backend/slam.h"

#include <stdexcept>
#include <string>
#include <utility>

#include <opencv2/core.hpp>

#include "dslam/core/stopwatch.h"
#include "dslam/features/features.h"

namespace dslam {
namespace {

/// OpenCV creates the operations of its matrix expressions (cv::Mat::zeros, comparisons such as
/// `labels == 3`) on their first use in the process (CV_SINGLETON_LAZY_INIT in OpenCV's
/// matrix_expressions.cpp), inside the uninstrumented library, so ThreadSanitizer sees no order
/// between that creation on one thread and a use on another (it reported the moving objects' and
/// the static map's dynamic masks, on the tracking and the back-end thread). Creating them before
/// the back-end thread starts orders the creation before every later use.
void CreateMatrixExpressionOperations() { cv::Mat unused = cv::Mat::zeros(1, 1, CV_8UC1); }

}  // namespace

Slam::Slam(const Config& config, BackEndMode mode, RefinedPoseRecording refined,
           std::vector<std::shared_ptr<KeyFrameObserver>> observers)
    : mode_(mode),
      refined_recording_(refined),
      observers_(std::move(observers)),
      errors_(std::make_shared<ErrorLog>()),
      odometry_(config) {
  if (mode_ == BackEndMode::kThreaded) {
    CreateMatrixExpressionOperations();
    back_end_ = std::thread(&Slam::BackEndLoop, this);
  }
}

FrameResult Slam::ProcessFrame(const RgbdFrame& frame, const FrameRequest& request) {
  const Stopwatch tracking;  // this thread's time: features, waiting for the lock, front end
  const std::string problem = frame.Check();
  if (!problem.empty()) throw std::invalid_argument("dslam: bad frame: " + problem);
  // Front end (Sec. V-A, V-B). ORB features with depth read nothing of the map: extracted
  // before the map lock is taken, so that the back end and loop closing are not kept waiting.
  const Stopwatch extraction;
  FrameFeatures features = ExtractFeatures(frame, config().features, config().depth_noise);
  const double features_ms = extraction.ElapsedMs();
  Lock lock(map_mutex_, &longest_hold_, "tracking");
  // Local-map matching, pose from static points, front-end static point determination, map
  // management and keyframes. The observers need the labels.
  FrameRequest front_end_request = request;
  if (!observers_.empty()) front_end_request.points = true;
  FrameResult result =
      odometry_.ProcessFrame(frame, std::move(features), features_ms, front_end_request);
  if (result.reset) {
    DropBackEndWork();  // the old world's keyframes and runs
    QueueReset(ResetMode::kNewWorld);
  }
  if (!observers_.empty()) QueueKeyFrame(frame, request.points, &result);
  if (result.reanchored && refined_recording_ == RefinedPoseRecording::kOn) {
    refined_.UpdateKeyFrames(map());  // the keyframes made since the weak episode moved
  }
  if (result.has_pose && refined_recording_ == RefinedPoseRecording::kOn) {
    refined_.AddFrame(result.stamp_s, result.T_world_camera, map());
  }
  if (mode_ == BackEndMode::kThreaded) ExchangeWithBackEnd(&result);
  result.times.tracking_ms = tracking.ElapsedMs();
  if (mode_ == BackEndMode::kThreaded) return result;
  // Back end (Sec. V): local mapping on the window the new keyframe completes.
  if (result.keyframe && config().backend.enabled) {
    // An error drops the run's results; this frame's pose stands and the next is tracked.
    errors_->Run("back end", [&] { result.backend = RunLocalMapping(); });
  }
  DeliverQueuedEvents(lock);
  return result;
}

void Slam::DeliverQueuedEvents(Lock& lock) {
  while (HasBackEndWork()) {  // synchronous: only the observers' events
    const Delivery delivery = TakeEvents();
    lock.unlock();
    Deliver(delivery);
    lock.lock();
  }
}

void Slam::QueueKeyFrame(const RgbdFrame& frame, bool keep_points, FrameResult* result) {
  if (result->keyframe && !map().window().empty()) {
    const KeyFrame& keyframe = map().window().back();  // made from this frame
    KeyFrameRecord record;
    record.id = keyframe.id;
    record.frame = frame;  // shallow: the images are shared, not copied
    record.T_world_camera = keyframe.T_world_camera;
    record.temporary = map().frozen();  // localisation only: made beside the frozen loaded map
    record.points = keep_points ? result->points : std::move(result->points);
    events_.keyframes.push_back(std::move(record));
  }
  if (!keep_points) result->points.clear();
}

void Slam::QueueReset(ResetMode mode) {
  if (observers_.empty()) return;
  events_.resets.emplace_back(events_.keyframes.size(), mode);
  events_.corrected.clear();  // of the world the reset ends
}

Slam::Delivery Slam::TakeEvents() {
  Delivery delivery = std::exchange(events_, Delivery());
  for (const KeyFrame& keyframe : map().window()) {
    delivery.window.push_back({keyframe.id, keyframe.T_world_camera});
  }
  return delivery;
}

void Slam::Deliver(const Delivery& delivery) const {
  // Keyframes in groups between resets; the window's poses belong to the newest group (the
  // observers forget or fix older groups at the reset that ends them).
  // Each observer's call on its own: an exception is reported and the next observer goes on.
  const auto each = [this](const std::function<void(KeyFrameObserver&)>& call) {
    for (const auto& observer : observers_) {
      errors_->Run(observer->name(), [&] { call(*observer); });
    }
  };
  size_t begin = 0;
  const auto deliver_keyframes = [&](size_t end) {
    if (end == begin) return;
    if (begin == 0 && end == delivery.keyframes.size()) {  // no reset among them: no copy
      each([&](KeyFrameObserver& o) { o.OnKeyFrames(delivery.keyframes, delivery.window); });
    } else {
      const std::vector<KeyFrameRecord> group(delivery.keyframes.begin() + begin,
                                              delivery.keyframes.begin() + end);
      each([&](KeyFrameObserver& o) { o.OnKeyFrames(group, delivery.window); });
    }
    begin = end;
  };
  for (const auto& [keyframes_before, mode] : delivery.resets) {
    deliver_keyframes(keyframes_before);
    each([mode = mode](KeyFrameObserver& o) { o.OnReset(mode); });
  }
  deliver_keyframes(delivery.keyframes.size());
  if (delivery.corrected.empty()) return;
  each([&](KeyFrameObserver& o) { o.OnCorrection(delivery.corrected); });
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
  status.window_keyframes = static_cast<int>(map().window().size());
  return status;
}

Slam::~Slam() {
  if (back_end_.joinable()) {
    {
      const Lock lock(map_mutex_, &longest_hold_, "stop");
      stop_ = true;  // a job in progress finishes, then the thread ends
    }
    work_.notify_all();
    back_end_.join();
  }
  for (const auto& observer : observers_) observer->OnStop();
}

void Slam::BackEndLoop() {
  Lock lock(map_mutex_, &longest_hold_, "back end");
  for (;;) {
    work_.wait(lock, [this] { return stop_ || (HasBackEndWork() && !held_); });
    if (stop_) return;  // queued keyframes and events are dropped
    const bool run_job = pending_ > 0;
    pending_ = 0;  // one run for all of them: the window of the newest keyframe
    running_ = true;
    bool stopped = false;
    // An error drops the run's results (and this round's events); tracking goes on.
    errors_->Run("back end", [&] {
      if (run_job) {
        LocalMappingJob job(map(), generation_);
        lock.unlock();  // tracking goes on while the job works on its copy
        job.Run(config());
        lock.lock();
        work_.wait(lock, [this] { return stop_ || !results_held_; });  // HoldBackEndResults
        stopped = stop_;  // the destructor: the results are dropped
        if (stopped) return;
        if (job.generation() == generation_) completed_.push_back(FinishLocalMapping(job));
      }
      if (!observers_.empty()) {  // the new keyframes and the window as local mapping left it
        const Delivery delivery = TakeEvents();
        lock.unlock();
        Deliver(delivery);
        lock.lock();
      }
    });
    if (!lock.owns_lock()) lock.lock();
    if (stopped) return;
    running_ = false;
    idle_.notify_all();
  }
}

void Slam::ExchangeWithBackEnd(FrameResult* result) {
  BackEndThreadStatus& thread = result->backend_thread;
  thread.threaded = true;
  if (result->keyframe && config().backend.enabled) ++pending_;
  // The back-end thread starts when this thread releases the lock.
  if (HasBackEndWork()) work_.notify_one();
  if (!completed_.empty()) {
    result->backend = completed_.front();
    completed_.pop_front();
    thread.delivered = true;
  }
  thread.backlog = pending_;
}

void Slam::Reset(ResetMode mode) {
  ResetOdometry(mode, [&] { odometry_.Reset(mode); }, {});
}

void Slam::StartInMap(Map map, std::shared_ptr<PlaceLookup> places, double timeout_s,
                      std::vector<KeyFrameRecord> loaded, LoadedMapUse use) {
  for (KeyFrameRecord& record : loaded) record.loaded = true;
  ResetOdometry(
      ResetMode::kNewWorld,
      [&] { odometry_.StartInMap(std::move(map), std::move(places), timeout_s, use); },
      std::move(loaded));
}

void Slam::SetPlaceLookup(std::shared_ptr<PlaceLookup> places) {
  Lock lock(map_mutex_, &longest_hold_, "control");
  odometry_.SetPlaceLookup(std::move(places));
}

bool Slam::Localising() const {
  Lock lock(map_mutex_, &longest_hold_, "control");
  return odometry_.localising();
}

void Slam::ResetOdometry(ResetMode mode, const std::function<void()>& reset,
                         std::vector<KeyFrameRecord> after_reset) {
  Lock lock(map_mutex_, &longest_hold_, "reset");
  DropBackEndWork();
  reset();
  QueueReset(mode);
  if (observers_.empty()) return;
  for (KeyFrameRecord& record : after_reset) events_.keyframes.push_back(std::move(record));
  if (mode_ == BackEndMode::kThreaded) {
    work_.notify_one();
    return;
  }
  DeliverQueuedEvents(lock);
}

void Slam::DropBackEndWork() {
  pending_ = 0;
  completed_.clear();
  ++generation_;  // a job in progress belongs to the old map
}

void Slam::WaitForBackEnd() {
  Lock lock(map_mutex_, &longest_hold_, "wait for the back end");
  if (mode_ == BackEndMode::kSynchronous) {
    DeliverQueuedEvents(lock);  // a correction made since the last frame
    return;
  }
  held_ = results_held_ = false;
  work_.notify_all();  // also wakes the thread for events queued without a frame (a correction)
  idle_.wait(lock, [this] { return !HasBackEndWork() && !running_; });
}

std::vector<BackEndStatus> Slam::TakeUnreportedRuns() {
  const Lock lock(map_mutex_, &longest_hold_, "control");
  std::vector<BackEndStatus> runs(completed_.begin(), completed_.end());
  completed_.clear();
  return runs;
}

void Slam::HoldBackEnd(bool hold) {
  {
    const Lock lock(map_mutex_, &longest_hold_, "control");
    held_ = hold && mode_ == BackEndMode::kThreaded;
  }
  work_.notify_all();
}

void Slam::HoldBackEndResults(bool hold) {
  {
    const Lock lock(map_mutex_, &longest_hold_, "control");
    results_held_ = hold && mode_ == BackEndMode::kThreaded;
  }
  work_.notify_all();
}

LockHold Slam::TakeLongestMapLockHold() {
  const Lock lock(map_mutex_, &longest_hold_, "lock meter");
  return std::exchange(longest_hold_, LockHold());
}

Trajectory Slam::RefinedPoses(double* lock_held_ms) const {
  RefinedTrajectory::Snapshot snapshot;
  {
    const Lock lock(map_mutex_, &longest_hold_, "refined trajectory");
    const Stopwatch held;
    snapshot = refined_.Take();  // a few block pointers and the keyframes in the map
    if (lock_held_ms != nullptr) *lock_held_ms = held.ElapsedMs();
  }
  return snapshot.Poses();
}

Map Slam::MapSnapshot() const {
  const Lock lock(map_mutex_, &longest_hold_, "map snapshot");
  return map();
}

void Slam::ReadMap(const std::function<void(const Map&)>& read) const {
  const Lock lock(map_mutex_, &longest_hold_, "map reader (loop detection)");
  read(map());
}

bool Slam::CorrectKeyFrames(const std::map<int, Eigen::Isometry3d>& T_world_camera_corrected) {
  return CorrectKeyFrames(T_world_camera_corrected, {});
}

bool Slam::CorrectKeyFrames(const std::map<int, Eigen::Isometry3d>& T_world_camera_corrected,
                            const std::map<int, Eigen::Isometry3d>& T_world_camera_before) {
  {
    const Lock lock(map_mutex_, &longest_hold_, "loop correction");
    if (!ApplyCorrection(T_world_camera_corrected, T_world_camera_before)) return false;
  }
  // Threaded: the back-end thread delivers the correction even when no frame follows.
  if (mode_ == BackEndMode::kThreaded && !observers_.empty()) work_.notify_one();
  return true;
}

bool Slam::ApplyCorrection(const std::map<int, Eigen::Isometry3d>& T_world_camera_corrected,
                           const std::map<int, Eigen::Isometry3d>& T_world_camera_before) {
  Map* live = odometry_.mutable_map();
  if (T_world_camera_corrected.empty() ||
      live->FindKeyFrame(T_world_camera_corrected.rbegin()->first) == nullptr) {
    return false;
  }
  live->CorrectKeyFrames(T_world_camera_corrected, T_world_camera_before);
  odometry_.AdoptNewestKeyFramePose();
  if (refined_recording_ == RefinedPoseRecording::kOn) refined_.FollowCorrection(map());
  if (!observers_.empty()) {  // delivered with the next events (the static map follows)
    events_.corrected.clear();
    for (const KeyFrame* keyframe : map().AllKeyFrames()) {
      events_.corrected.push_back({keyframe->id, keyframe->T_world_camera});
    }
  }
  return true;
}

}  // namespace dslam
