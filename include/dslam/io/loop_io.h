#pragma once
// Loop files (`dslam_run_dataset --loops`, read by `dslam_eval --loops`): one accepted loop per
// line, `stamp_query stamp_match tx ty tz qx qy qz qw`, the pose of the query keyframe's camera
// (optical frame) in the matched keyframe's camera frame, T_match_query, as estimated when the
// loop was accepted; stamps in seconds, '#' comments.

#include <istream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace dslam {

/// One accepted loop.
struct LoopRecord {
  double stamp_query_s = 0.0;  ///< [s] stamp of the keyframe that recognised the place
  double stamp_match_s = 0.0;  ///< [s] stamp of the older keyframe it was matched with
  /// [m] query camera -> matched camera (optical frames), as estimated at acceptance.
  Eigen::Isometry3d T_match_query = Eigen::Isometry3d::Identity();
};

/// Reads a loop file in the order of its lines; quaternions are normalised. Throws
/// std::runtime_error naming the file and line on malformed input.
std::vector<LoopRecord> ReadLoopFile(const std::string& path);

/// Same as ReadLoopFile, from a stream; `name` (the file's name) starts each message.
std::vector<LoopRecord> ParseLoopFile(std::istream& in, const std::string& name);

/// Writes `loops` with a header comment (stamps with 6 decimals, positions 6, quaternions 7).
/// Throws std::runtime_error when the file cannot be written.
void WriteLoopFile(const std::string& path, const std::vector<LoopRecord>& loops);

}  // namespace dslam
