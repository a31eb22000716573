#pragma once
// Judges accepted loops (dslam/io/loop_io.h) against ground truth: a loop is false when its
// estimated relative pose T_match_query differs from the true one by more than a translation or
// a rotation bound (defaults 0.10 m and 3 deg). A relative pose needs no trajectory alignment.

#include <vector>

#include "dslam/core/trajectory.h"
#include "dslam/io/loop_io.h"

namespace dslam {

/// Bounds of the check.
struct LoopCheckOptions {
  double max_translation_m = 0.10;  ///< [m] largest error of a true loop's relative translation
  double max_rotation_deg = 3.0;    ///< [deg] largest error of a true loop's relative rotation
  /// [s] ground truth is interpolated between the two poses around a stamp when they are at most
  /// this far apart; a loop with a stamp outside that is not checked.
  double max_groundtruth_gap_s = 0.1;
};

/// The verdict on one loop.
struct LoopVerdict {
  LoopRecord loop;
  bool checked = false;              ///< ground truth covers both stamps
  double translation_error_m = 0.0;  ///< [m] |t of T_true^-1 T_estimated|
  double rotation_error_deg = 0.0;   ///< [deg] angle of T_true^-1 T_estimated
  double true_distance_m = 0.0;      ///< [m] true distance between the two camera centres
  bool false_loop = false;           ///< checked and beyond a bound
};

/// All verdicts and their counts.
struct LoopCheck {
  std::vector<LoopVerdict> verdicts;     ///< in the order of the loops
  int checked = 0;                       ///< loops with ground truth at both stamps
  int false_loops = 0;                   ///< checked loops beyond a bound
  double max_translation_error_m = 0.0;  ///< [m] over the checked loops (0 when none)
  double max_rotation_error_deg = 0.0;   ///< [deg] over the checked loops (0 when none)
};

/// Ground-truth T_world_camera at `stamp_s` [s]: position linear and rotation slerp between the
/// poses around it (exact at a pose's stamp). False when the stamp is outside the trajectory or
/// the poses around it are more than `max_gap_s` [s] apart. `groundtruth` is sorted by stamp.
bool InterpolatePose(const Trajectory& groundtruth, double stamp_s, double max_gap_s,
                     Eigen::Isometry3d* T_world_camera);

/// Checks every loop against `groundtruth` (sorted by stamp, e.g. ReadTumTrajectory's).
LoopCheck CheckLoops(const std::vector<LoopRecord>& loops, const Trajectory& groundtruth,
                     const LoopCheckOptions& options = {});

}  // namespace dslam
