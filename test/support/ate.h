#pragma once
// The absolute trajectory error the whole-trajectory tests bound (link dslam_eval).

#include "dslam/core/trajectory.h"
#include "dslam/eval/trajectory_metrics.h"

namespace dslam {
namespace test {

/// RMSE of the absolute trajectory error [m] of `estimated` against `groundtruth` (both
/// T_world_camera by stamp), after EvaluateTrajectory's alignment with default options.
inline double AteRmse(const Trajectory& estimated, const Trajectory& groundtruth) {
  return EvaluateTrajectory(estimated, groundtruth, {}, TrajectoryMetricsOptions()).ate_m.rmse;
}

}  // namespace test
}  // namespace dslam
