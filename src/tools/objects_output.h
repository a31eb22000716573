#pragma once
// dslam_run_dataset --objects: the moving objects of every frame (MovingObjectTracker, part
// mapping) and their file, one line per frame and reported object:
//   timestamp id x y z vx vy vz ex ey ez
// [s], [-], position [m], velocity [m/s] and full extent [m], all in the trajectory's frame (the
// odometry world frame: the first frame's optical frame).

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "dslam/core/config.h"
#include "dslam/core/ordered_worker.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/mapping/moving_object_tracker.h"
#include "dslam/tracking/frame_result.h"

namespace dslam {
namespace tools {

/// Runs MovingObjectTracker on each frame and writes the objects file; times each frame's work.
/// WorkerMode::kThreaded (--threads): the frames are tracked in order on a worker thread of
/// their own (OrderedWorker), beside the tracking thread; kSynchronous: inside Add. The file is
/// the same either way (the tracker sees the same frames in the same order). An error while
/// tracking a frame is thrown by Add of that frame (synchronous) or by a later Add or Close
/// (threaded: the frames queued after it are tracked first).
class ObjectsOutput {
 public:
  /// Opens `path` and writes the header; throws std::runtime_error when it cannot.
  ObjectsOutput(const std::string& path, const Config& config, WorkerMode mode);

  /// Hands one frame (after Slam::ProcessFrame) to the tracker, which appends its objects'
  /// lines. Threaded, blocks while two frames wait for the worker.
  void Add(const RgbdFrame& frame, const FrameResult& result);

  /// Waits for the worker and flushes; throws std::runtime_error when the file could not be
  /// written. Call before reading the counters below.
  void Close();

  /// [ms] wall time of each frame's dynamic mask and tracking (on the worker thread when threaded).
  const std::vector<double>& times_ms() const { return times_ms_; }
  /// [ms] wall time of each Add on the caller's (tracking) thread: the whole work when
  /// synchronous; when threaded, copying the frame's result and queueing it, and waiting while
  /// two frames are queued.
  const std::vector<double>& add_times_ms() const { return add_times_ms_; }
  int object_frames() const { return object_frames_; }  ///< lines written

 private:
  /// The worker's part of Add: tracks and writes one frame.
  void Track(const RgbdFrame& frame, const FrameResult& result);

  std::string path_;
  std::ofstream out_;
  MovingObjectTracker objects_;  ///< the worker's alone (OrderedWorker's locking policy)
  std::vector<double> times_ms_;
  std::vector<double> add_times_ms_;
  int object_frames_ = 0;
  OrderedWorker worker_;  ///< last: its destructor runs the queued frames before the above go
};

}  // namespace tools
}  // namespace dslam
