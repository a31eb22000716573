#pragma once
// dslam_run_dataset --objects: the moving objects of every frame (MovingObjectTracker, part mapping)
// and their file, one line per frame and reported object:
//   timestamp id x y z vx vy vz ex ey ez
// [s], [-], position [m], velocity [m/s] and full extent [m], all in the trajectory's frame (the
// odometry world frame: the first frame's optical frame).

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "dslam/core/config.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/mapping/moving_object_tracker.h"
#include "dslam/tracking/frame_result.h"

namespace dslam {
namespace tools {

/// Runs MovingObjectTracker on each frame and writes the objects file; times each frame's work.
class ObjectsOutput {
 public:
  /// Opens `path` and writes the header; throws std::runtime_error when it cannot.
  ObjectsOutput(const std::string& path, const Config& config);

  /// Tracks the objects of one frame (after Slam::ProcessFrame) and appends their lines.
  void Add(const RgbdFrame& frame, const FrameResult& result);

  /// Flushes; throws std::runtime_error when the file could not be written.
  void Close();

  /// [ms] wall time of each Add (dynamic mask and tracking, on the tracking thread).
  const std::vector<double>& times_ms() const { return times_ms_; }
  int object_frames() const { return object_frames_; }  ///< lines written

 private:
  std::string path_;
  std::ofstream out_;
  MovingObjectTracker objects_;
  std::vector<double> times_ms_;
  int object_frames_ = 0;
};

}  // namespace tools
}  // namespace dslam
