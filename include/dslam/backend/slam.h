#pragma once
// The whole pipeline of the paper: the front end (Odometry: ORB tracking against the local map
// with front-end static point determination) on every frame and, after each new keyframe, the
// back end (local mapping: local bundle adjustment over the keyframe window) on the same map.
//
// Two execution modes (BackEndMode). Synchronous (the default, deterministic: the reference for
// offline runs): local mapping runs inside ProcessFrame, before the next frame is read.
// Threaded (the ROS node's default): local mapping runs on Slam's own back-end thread beside
// the caller's (tracking) thread.
//
// Locking policy (threaded mode; synchronous mode takes the same lock, uncontended). One mutex,
// the map mutex, guards all mutable state of Slam: the Odometry (its map, motion model and frame
// bookkeeping), the RefinedTrajectory and the back-end queue (pending keyframes, the run in
// progress flag, completed runs, the hold and stop flags, the reset generation).
// - The tracking thread (the caller of ProcessFrame) holds it for Odometry::ProcessFrame and the
//   bookkeeping after it (refined trajectory, queueing the keyframe, handing over a completed
//   run), then releases it before returning.
// - The back-end thread holds it only to copy the keyframe window into a LocalMappingJob and,
//   after the run, to apply the job's results to the map (keyframe poses, moved points, lost
//   marks), correct the motion model and the refined trajectory. It runs the job (static point
//   determination and local BA on the copy, the expensive part) without the lock: the job's copy
//   is the back-end thread's alone. A Reset while a job runs increments the generation; the job's
//   results are then dropped.
// - Every other public member (Reset, StartInMap, Localising, SetPlaceLookup, WaitForBackEnd,
//   TakeUnreportedRuns, RefinedPoses, MapSnapshot, ReadMap, CorrectKeyFrames; the tests' holds)
//   takes it; getters return copies, never references into the map. config() is immutable.
// - Keyframe observers (keyframe_observer.h, given to the constructor; the static map): under the
//   lock the tracking thread queues each new keyframe (a shallow copy of its images and its point
//   labels) and each reset as events. The thread that delivers them takes the queue and the
//   window's poses under the lock and calls the observers after releasing it: threaded, the
//   back-end thread after its local mapping run (or without one when the back end is off);
//   synchronous, the caller at the end of ProcessFrame and Reset. Observers may take locks of
//   their own: none is ever held together with the map mutex.
// - Errors: an exception of a back-end run or of an observer's call is reported to errors()
//   (ErrorLog, its own lock) where it happened and never rethrown into another call: the other
//   observers still get their events, the next frame is tracked.
// Nothing else is shared between the threads; no other lock is taken while it is held (but the
// ErrorLog's, which takes no other).

#include <condition_variable>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "dslam/backend/keyframe_observer.h"
#include "dslam/backend/local_bundle_adjustment.h"
#include "dslam/backend/local_mapping_job.h"
#include "dslam/backend/refined_trajectory.h"
#include "dslam/backend/timed_lock.h"
#include "dslam/core/config.h"
#include "dslam/core/error_log.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/tracking/frame_result.h"
#include "dslam/tracking/odometry.h"

namespace dslam {

/// Where Slam runs local mapping after a keyframe.
enum class BackEndMode {
  kSynchronous,  ///< inside ProcessFrame, after the front end (deterministic)
  kThreaded,     ///< on Slam's back-end thread, beside the caller's tracking thread
};

/// Whether Slam keeps every tracked frame for RefinedPoses() (memory grows by one entry per
/// tracked frame and one per keyframe: offline runs want it, a node running for hours does not).
enum class RefinedPoseRecording {
  kOn,   ///< RefinedPoses() returns every tracked frame
  kOff,  ///< RefinedPoses() returns nothing; memory stays flat
};

/// Front end and back end over one map. ProcessFrame, Reset, WaitForBackEnd and
/// TakeUnreportedRuns are for one (tracking) thread; the getters may be called from any thread
/// (locking policy above).
class Slam {
 public:
  /// Starts the back-end thread in BackEndMode::kThreaded. `observers` receive every keyframe
  /// and reset (locking policy above); with any, every frame's FrameResult::points are computed
  /// (returned only when the request asks for them). Throws ConfigError when `config` is invalid.
  explicit Slam(const Config& config, BackEndMode mode = BackEndMode::kSynchronous,
                RefinedPoseRecording refined = RefinedPoseRecording::kOn,
                std::vector<std::shared_ptr<KeyFrameObserver>> observers = {});
  /// Stops the back-end thread: waits for a run in progress, drops keyframes still queued; then
  /// tells every observer (KeyFrameObserver::OnStop).
  ~Slam();
  Slam(const Slam&) = delete;
  Slam& operator=(const Slam&) = delete;

  /// Tracks one frame (Odometry::ProcessFrame) and, when it became a keyframe and
  /// backend.enabled, runs local mapping (synchronous) or queues it for the back-end thread
  /// (threaded). FrameResult::backend is, synchronous: this keyframe's run; threaded: the oldest
  /// completed run not yet reported, flagged by FrameResult::backend_thread.delivered (each run is
  /// reported once; TakeUnreportedRuns returns the rest). The pose in the result is the one
  /// estimated at this frame (causal). Sets times.tracking_ms. `request` chooses the per-frame
  /// lists (FrameRequest). When time went backwards the odometry starts a new world
  /// (FrameResult::reset) and queued keyframes and unreported runs of the old one are dropped.
  /// Throws std::invalid_argument when frame.Check() fails.
  FrameResult ProcessFrame(const RgbdFrame& frame, const FrameRequest& request = {});

  /// Drops queued keyframes, unreported runs and the results of a run in progress (which goes on
  /// with its own copy of the window), then resets the odometry (Odometry::Reset): the next frame
  /// initialises at the last tracked pose (kKeepPose) or at the world origin (kNewWorld). The
  /// observers see the reset after the keyframes made before it (threaded: on the back-end
  /// thread, WaitForBackEnd waits for it).
  void Reset(ResetMode mode);

  /// As Reset(ResetMode::kNewWorld), then the odometry starts in `map` (a loaded keyframe map;
  /// Odometry::StartInMap: no pose until a frame is relocalised in it at a place `places` names,
  /// a new world after `timeout_s` [s] without). The observers then receive `loaded` (keyframes
  /// of `map` with their images, flagged KeyFrameRecord::loaded) after the reset, as Reset's
  /// events are delivered: the static map fuses them, loop closing enters them in its database.
  /// With LoadedMapUse::kLocalisationOnly the loaded map stays as loaded (Odometry::StartInMap)
  /// and the keyframes made later reach the observers as KeyFrameRecord::temporary. Throws
  /// std::invalid_argument as StartInMap.
  void StartInMap(Map map, std::shared_ptr<PlaceLookup> places, double timeout_s,
                  std::vector<KeyFrameRecord> loaded = {},
                  LoadedMapUse use = LoadedMapUse::kExtend);
  /// Between StartInMap and the first frame localised in its map (Odometry::localising).
  bool Localising() const;
  /// Place recognition over the whole keyframe map for lost frames (Odometry::SetPlaceLookup);
  /// call before the first frame. `places` is called from the tracking thread only.
  void SetPlaceLookup(std::shared_ptr<PlaceLookup> places);

  /// Returns when no keyframe is queued, no run is in progress and the observers have every
  /// event, including a correction queued since the last frame (CorrectKeyFrames). Threaded:
  /// releases both holds, then waits for the back-end thread. Synchronous: delivers the queued
  /// events on the calling thread.
  void WaitForBackEnd();

  /// The completed runs no FrameResult has reported, oldest first; they count as reported (the
  /// end of a threaded run: WaitForBackEnd, then this). Always empty when synchronous.
  std::vector<BackEndStatus> TakeUnreportedRuns();

  /// Every tracked frame re-expressed on its reference keyframe as refined by the back end so
  /// far (RefinedTrajectory, a copy); the same poses as the causal ones with the back end off.
  /// The map lock is held only to copy RefinedTrajectory::Take (O(keyframes in the map), not
  /// O(frames)); `lock_held_ms` [ms], when given, receives how long.
  Trajectory RefinedPoses(double* lock_held_ms = nullptr) const;

  /// A copy of the map (keyframe window and points) between two runs of either thread.
  Map MapSnapshot() const;

  /// Calls `read(map)` under the map lock, for consumers above the back end that need part of
  /// the map without copying all of it (loop detection). Tracking waits meanwhile: keep it short.
  void ReadMap(const std::function<void(const Map&)>& read) const;

  /// Moves keyframes by a loop correction (Map::CorrectKeyFrames) under the map lock: each
  /// keyframe of `T_world_camera_corrected` moves by corrected * before^-1, where before is its
  /// pose in `T_world_camera_before` (the poses the correction was computed from), so that what
  /// local mapping refined since is kept. The last tracked pose follows its keyframe (the next
  /// frame reports it as T_world_previous_camera), the refined trajectory takes the new poses, a
  /// local-mapping run copied before it does not write its poses back, and the observers receive
  /// the corrected poses (OnCorrection) with the next delivery or WaitForBackEnd. False, and
  /// nothing changed, when the newest corrected keyframe is not in the map any more (a reset came
  /// between). Poses [m], camera optical frame -> world.
  bool CorrectKeyFrames(const std::map<int, Eigen::Isometry3d>& T_world_camera_corrected,
                        const std::map<int, Eigen::Isometry3d>& T_world_camera_before);
  /// As above with every `before` pose the keyframe's present one.
  bool CorrectKeyFrames(const std::map<int, Eigen::Isometry3d>& T_world_camera_corrected);

  /// The longest hold of the map lock since the last call (or construction), and its holder
  /// ("tracking", "back end", "map reader (loop detection)", "refined trajectory", ...); resets it.
  LockHold TakeLongestMapLockHold();

  /// Errors of back-end runs and observers (shared: loop closing reports its own here).
  std::shared_ptr<ErrorLog> errors() const { return errors_; }

  const Config& config() const { return odometry_.config(); }  ///< immutable
  BackEndMode mode() const { return mode_; }                   ///< as constructed

 private:
  friend class SlamTestAccess;  // tests: the two holds below (test/support/slam_test_access.h)
  using Lock = TimedLock;

  /// Threaded: while held, keyframes queue (the backlog grows) and no run starts; releasing
  /// starts one run for the newest (as when the thread is busy): tests see the queue. No effect
  /// when synchronous.
  void HoldBackEnd(bool hold);

  /// Threaded: while held, a run that has copied its window works on its copy, then waits
  /// (without the lock) before applying its results, so that the map changes only by tracking
  /// while the run is in flight, for as many frames as the caller feeds (tests of the locking
  /// policy). New keyframes queue meanwhile. Releasing lets the run apply. No effect when
  /// synchronous.
  void HoldBackEndResults(bool hold);

  /// Drops the back end's work, calls `reset` (which resets the odometry), queues a reset of
  /// `mode` and then `after_reset` for the observers, delivering them as Reset describes.
  void ResetOdometry(ResetMode mode, const std::function<void()>& reset,
                     std::vector<KeyFrameRecord> after_reset);
  /// Synchronous local mapping on the window the newest keyframe completes (lock held): the
  /// same job as the back-end thread's, copied, run and applied at once.
  BackEndStatus RunLocalMapping();
  /// Applies a finished job to the live map and corrects tracking (lock held).
  BackEndStatus FinishLocalMapping(const LocalMappingJob& job);
  /// The back-end thread: waits for queued keyframes, runs local mapping once for all of them,
  /// then delivers the observers' events.
  void BackEndLoop();
  /// Threaded bookkeeping after the front end (queue a keyframe, hand over a run); lock held.
  void ExchangeWithBackEnd(FrameResult* result);
  /// Keyframes queued for local mapping or events for the observers (lock held).
  bool HasBackEndWork() const {
    return pending_ > 0 || !events_.keyframes.empty() || !events_.resets.empty() ||
           !events_.corrected.empty();
  }
  /// Events for the observers: keyframes and resets in the order they happened, and the
  /// window's poses when they were taken.
  struct Delivery {
    std::vector<KeyFrameRecord> keyframes;             ///< oldest first
    std::vector<std::pair<size_t, ResetMode>> resets;  ///< (keyframes made before it, mode)
    std::vector<KeyFramePose> window;                  ///< filled by TakeEvents
    /// Every keyframe's pose after the newest correction since the last reset; empty: none.
    std::vector<KeyFramePose> corrected;
  };
  /// Queues `result`'s keyframe for the observers (lock held); moves the points out of `result`
  /// unless `keep_points`.
  void QueueKeyFrame(const RgbdFrame& frame, bool keep_points, FrameResult* result);
  void QueueReset(ResetMode mode);  ///< queues a reset for the observers; lock held
  Delivery TakeEvents();            ///< the queued events with the window's poses; lock held
  /// Calls the observers with `delivery`'s events in order (without the lock); an observer's
  /// exception goes to errors_ and the others still get the event.
  void Deliver(const Delivery& delivery) const;
  /// Synchronous: delivers queued events on this thread until none are left (an observer may
  /// queue more, a loop correction); `lock` is held on entry and on return.
  void DeliverQueuedEvents(Lock& lock);
  void DropBackEndWork();  ///< forgets queued keyframes and unreported runs; lock held
  /// CorrectKeyFrames' work on the map, the tracker and the observers' queue; lock held.
  bool ApplyCorrection(const std::map<int, Eigen::Isometry3d>& T_world_camera_corrected,
                       const std::map<int, Eigen::Isometry3d>& T_world_camera_before);
  const Map& map() const { return odometry_.map(); }  ///< lock held

  const BackEndMode mode_;
  const RefinedPoseRecording refined_recording_;
  const std::vector<std::shared_ptr<KeyFrameObserver>> observers_;  ///< as constructed
  const std::shared_ptr<ErrorLog> errors_;  ///< its own lock, not the map mutex
  mutable std::mutex map_mutex_;   ///< the one lock: guards every member below (policy above)
  mutable LockHold longest_hold_;  ///< of map_mutex_ since the last TakeLongestMapLockHold
  Odometry odometry_;
  RefinedTrajectory refined_;
  std::condition_variable_any work_;     ///< back-end thread: work queued, hold released or stop
  std::condition_variable_any idle_;     ///< WaitForBackEnd: a run finished
  int pending_ = 0;                      ///< [keyframes] queued and not started (the backlog)
  bool running_ = false;                 ///< the back-end thread works on a job (without the lock)
  uint64_t generation_ = 0;              ///< incremented by each reset: older jobs are dropped
  bool held_ = false;                    ///< HoldBackEnd(true)
  bool results_held_ = false;            ///< HoldBackEndResults(true)
  bool stop_ = false;                    ///< the destructor asked the thread to end
  std::deque<BackEndStatus> completed_;  ///< runs not yet reported, oldest first
  Delivery events_;                      ///< for the observers, not yet taken
  std::thread back_end_;                 ///< started last, threaded mode only
};

}  // namespace dslam
