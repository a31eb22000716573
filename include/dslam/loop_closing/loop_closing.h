#pragma once
// Loop closing over Slam's keyframe map (issue 33): a KeyFrameObserver that, for each new keyframe,
// looks for a place seen before (LoopDetector: words of verified static points, consistency over
// consecutive keyframes, 3D-3D verification on static points only), and for a verified loop
// optimises the keyframe map's pose graph (loop_correction.h) and moves the keyframes and their
// points (Slam::CorrectKeyFrames), which carries the correction to the current pose. Temporary
// keyframes (KeyFrameRecord::temporary: a run that localises only in a loaded map) are left
// out: neither entered in the database nor searched, so no loop moves the loaded map.
//
// Threads: Slam calls OnKeyFrames and OnReset without holding its map lock (keyframe_observer.h):
// on its back-end thread in threaded mode, on the caller's in synchronous mode. They post the
// work, in order, to loop closing's OrderedWorker: WorkerMode::kThreaded runs it on loop
// closing's own thread (so a loop's pose graph never delays local mapping), kSynchronous inside
// the call (deterministic). The detector, the database bookkeeping and the loop edges are the
// worker's alone. Detection and the graph's construction run under the map lock (Slam::ReadMap;
// tracking waits that long), the solve without it, the correction under it again
// (Slam::CorrectKeyFrames). This class's own mutex guards only the list of loops and the times,
// and is never held while calling Slam. OnStop (from ~Slam) skips the keyframes still queued and
// waits for the one in progress; nothing calls Slam after it.

#include <atomic>
#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "dslam/backend/keyframe_observer.h"
#include "dslam/backend/slam.h"
#include "dslam/core/config.h"
#include "dslam/core/error_log.h"
#include "dslam/core/ordered_worker.h"
#include "dslam/loop_closing/loop_correction.h"
#include "dslam/loop_closing/loop_detector.h"
#include "dslam/place_recognition/vocabulary.h"

namespace dslam {

/// After an accepted loop, this many keyframes are not searched for loops (ORB-SLAM2 waits 10):
/// the tracker needs them to take up the corrected map.
constexpr int kKeyFramesAfterLoop = 10;

/// Keyframes waiting for loop closing's thread at most (WorkerMode::kThreaded).
constexpr int kMaxQueuedKeyFrames = 16;

/// LoopClosing::times_ms keeps the times of this many newest keyframes (memory stays bounded over
/// hours; LoopWork::keyframes counts them all).
constexpr size_t kKeptTimes = 4096;

/// Keyframes between two removals of erased keyframes from the place database.
constexpr int kPruneKeyFrames = 50;

/// A loop that was verified and corrected.
struct ClosedLoop {
  LoopDetection detection;        ///< as verified (before the correction)
  double query_moved_m = 0.0;     ///< [m] how far the correction moved the query keyframe
  double query_turned_deg = 0.0;  ///< [deg] and turned it
};

/// How much loop closing has done (LoopClosing::work).
struct LoopWork {
  int loops = 0;         ///< [-] loops closed
  int keyframes = 0;     ///< [-] keyframes processed (and timed)
  double last_ms = 0.0;  ///< [ms] the newest keyframe's time; 0 before the first
  int dropped = 0;       ///< [-] verified loops not closed (solve failed, or refused by Slam)
};

/// Loop closing as at the top of this file.
class LoopClosing : public KeyFrameObserver {
 public:
  /// `vocabulary` (shared, read-only) gives the keyframes' words; thresholds from
  /// config.loop_closing.
  /// `mode`: where keyframes are processed (top of this file); threaded, at most
  /// kMaxQueuedKeyFrames wait and OnKeyFrames blocks beyond that.
  LoopClosing(const Config& config, std::shared_ptr<const Vocabulary> vocabulary,
              WorkerMode mode = WorkerMode::kSynchronous);

  /// The Slam whose map is searched and corrected; call before its first frame. `slam` must
  /// outlive this object's use by it. The same vocabulary serves `slam`'s lost frames: a frame
  /// that cannot be relocalised in the window is tried at the places MapPlaces names in the whole
  /// keyframe map (Slam::SetPlaceLookup).
  void Attach(Slam* slam);

  void OnKeyFrames(const std::vector<KeyFrameRecord>& added,
                   const std::vector<KeyFramePose>& window) override;
  void OnReset(ResetMode mode) override;
  void OnStop() override;

  /// Returns when every keyframe given so far was processed (threaded: by loop closing's thread);
  /// rethrows an error of that work. Call from the thread that delivers keyframes, or after it
  /// stopped (e.g. after Slam::WaitForBackEnd).
  void Wait();

  /// The loops closed so far, oldest first (a copy; any thread).
  std::vector<ClosedLoop> loops() const;
  /// [ms] time spent per keyframe (detection, and correction when a loop was closed), for the
  /// newest kKeptTimes keyframes, oldest first.
  std::vector<double> times_ms() const;
  /// The number of loops() and of times_ms(), and the newest time, without copying them (any
  /// thread): what a status message shows at every keyframe of a run of any length.
  LoopWork work() const;
  /// Errors of loop closing's work (a keyframe's exception, a verified loop dropped), each
  /// reported once where it happened; any thread.
  std::shared_ptr<ErrorLog> errors() const { return errors_; }
  std::string name() const override { return "loop closing"; }

 private:
  /// One keyframe of OnKeyFrames, on the worker: into the database (loaded), skipped
  /// (temporary) or searched and timed.
  void HandleKeyFrame(int id, bool loaded, bool temporary,
                      const std::shared_ptr<const PinholeCamera>& camera);
  /// Detection for keyframe `id` and, for a loop, its correction; true when one was closed.
  bool ProcessKeyFrame(int id);
  /// A keyframe of a loaded map (KeyFrameRecord::loaded) into the database, without a search.
  void AddLoadedKeyFrame(int id);
  /// Erases from the database the keyframes `map` no longer has.
  void PruneErased(const Map& map);

  Slam* slam_ = nullptr;
  LoopClosingConfig config_;
  PoseConfig pose_config_;
  std::shared_ptr<const Vocabulary> vocabulary_;
  /// Made at the first keyframe, with its camera (the image quadrants of the verification).
  std::unique_ptr<LoopDetector> detector_;
  int keyframes_since_loop_ = kKeyFramesAfterLoop;
  /// Keyframe ids in the detector's database; those the map erased leave it every
  /// kPruneKeyFrames keyframes, so that it stays as bounded as the map (tracking.max_keyframes).
  std::vector<int> in_database_;
  /// Accepted loops whose keyframes are both in the map, for the next loop's pose graph (pruned
  /// with the database).
  std::vector<LoopEdge> loop_edges_;
  mutable std::mutex mutex_;  ///< guards loops_, times_ms_, keyframes_timed_, dropped_loops_
  std::vector<ClosedLoop> loops_;
  int dropped_loops_ = 0;
  std::deque<double> times_ms_;  ///< the newest kKeptTimes
  int keyframes_timed_ = 0;
  std::atomic<bool> stopping_{false};       ///< OnStop began: queued keyframes are skipped
  const std::shared_ptr<ErrorLog> errors_;  ///< its own lock; given to worker_
  /// Runs the keyframes' work in order; declared last, so that its thread ends (destroyed first)
  /// before the members its tasks use.
  std::unique_ptr<OrderedWorker> worker_;
};

}  // namespace dslam
