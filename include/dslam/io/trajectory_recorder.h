#pragma once
// The poses a running odometry has tracked, kept for saving: in segments (a new segment starts when
// the odometry restarts in a new world frame, e.g. time went backwards), in memory or streamed to a
// file as they arrive (memory then stays flat on long runs). Saving is split in two so that a
// caller holding a lock only copies (Snapshot) and writes the files after releasing it
// (WriteTrajectorySnapshot).

#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "dslam/core/trajectory.h"

namespace dslam {

/// The file of earlier segment `n` (1 = the oldest) beside `path`: "<stem>.seg<n><ext>"
/// (out/traj.txt -> out/traj.seg1.txt; a name without extension gets ".seg<n>" appended).
std::string SegmentPath(const std::string& path, int n);

/// Everything needed to write the recorded segments, taken under the recorder owner's lock.
struct TrajectorySnapshot {
  /// In memory: the segments' poses, oldest first; the last is the current segment.
  std::vector<Trajectory> segments;
  /// Streaming: each segment's file, opened at the snapshot (so later renames do not matter),
  /// with its size then [bytes]; oldest first.
  struct StreamedSegment {
    std::string path;
    std::shared_ptr<std::ifstream> file;
    std::uintmax_t bytes = 0;
  };
  std::vector<StreamedSegment> streamed;
  std::uintmax_t poses = 0;  ///< poses in all segments
};

/// Writes `snapshot` in TUM format: the current (last) segment to `path`, each earlier one to
/// SegmentPath(path, n), n = 1 the oldest; removes SegmentPath(path, k) files left by an earlier
/// save for k beyond the earlier segments. Returns the poses written. Writing to the stream's own
/// path leaves the streamed files as they are. Throws std::runtime_error naming the file.
std::uintmax_t WriteTrajectorySnapshot(const TrajectorySnapshot& snapshot, const std::string& path);

/// Records tracked poses in segments. Not thread-safe: the owner serialises the calls.
class TrajectoryRecorder {
 public:
  /// `stream_path` empty: poses are kept in memory. Otherwise the file is created (truncated)
  /// here, each pose is appended and flushed as it is added, and none is kept in memory; when a
  /// new segment starts the file is renamed to SegmentPath(stream_path, n) and a new one begun.
  /// Throws std::runtime_error when the file cannot be written.
  explicit TrajectoryRecorder(std::string stream_path = "");

  /// Appends a pose to the current segment. Throws std::runtime_error on a write error.
  void Add(const StampedPose& pose);
  /// Closes the current segment and begins a new one (no effect while the current is empty).
  void StartSegment();
  /// Copies (memory) or opens (streaming) what WriteTrajectorySnapshot needs.
  TrajectorySnapshot Snapshot() const;

  std::uintmax_t num_poses() const { return poses_; }  ///< in all segments
  int num_segments() const { return static_cast<int>(segment_poses_.size()); }
  const std::string& stream_path() const { return stream_path_; }

 private:
  void OpenStream();

  std::string stream_path_;
  std::vector<Trajectory> segments_;           ///< in memory only
  std::vector<std::uintmax_t> segment_poses_;  ///< poses per segment, oldest first
  std::vector<std::uintmax_t> segment_bytes_;  ///< streaming: bytes per segment file
  std::uintmax_t poses_ = 0;
  std::ofstream stream_;
};

}  // namespace dslam
