#pragma once
// Trajectories in TUM format: one pose per line, `timestamp tx ty tz qx qy qz qw`, the pose of the
// colour camera's optical frame in the world (T_world_camera), stamps in seconds, '#' comments.

#include <istream>
#include <string>

#include "dslam/core/trajectory.h"

namespace dslam {

/// Reads a TUM trajectory file; quaternions are normalised, lines are sorted by stamp.
/// Throws std::runtime_error naming the file and line on malformed input.
Trajectory ReadTumTrajectory(const std::string& path);

/// Same as ReadTumTrajectory, from a stream; `name` (the file's name) starts each message.
Trajectory ParseTumTrajectory(std::istream& in, const std::string& name);

/// Writes `trajectory` in TUM format (stamps with 6 decimals, positions 6, quaternions 7),
/// with a header comment. Throws std::runtime_error when the file cannot be written.
void WriteTumTrajectory(const std::string& path, const Trajectory& trajectory);

/// The comment line (with its newline) that begins every trajectory file dslam writes.
extern const char kTumTrajectoryHeader[];

/// Formats one pose as a TUM line without newline.
std::string FormatTumLine(const StampedPose& pose);

/// Reads up to the next line that is neither blank nor a '#' comment into `line`; false at the end
/// of `in`. `line_number` counts every line read (1-based), for messages.
bool ReadDataLine(std::istream& in, std::string* line, int* line_number);

/// The pose of TUM fields `tx ty tz qx qy qz qw` [m]; the quaternion is normalised. Throws
/// std::runtime_error(where + "zero quaternion") when its norm is below 1e-6 (or not finite).
Eigen::Isometry3d PoseFromTumFields(const double fields[7], const std::string& where);

}  // namespace dslam
