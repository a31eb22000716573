#pragma once
// Where the frame of dslam_run_dataset's outputs (trajectory, map, objects: the first frame's
// optical frame) lies in the ground truth's world, for measurements that compare those outputs
// with world-frame truth without aligning them (object_metrics.h, map_metrics.h).

#include <Eigen/Geometry>

#include "dslam/core/trajectory.h"

namespace dslam {

/// T_world_estworld: with an estimated trajectory, T_world_camera(gt, t0) *
/// T_estworld_camera(t0)^-1 at the stamp t0 of its first pose (so an estimate whose first pose is
/// not the identity, e.g. when tracking began after the first frame, is placed right); without one
/// (empty), the ground-truth pose nearest to `first_frame_stamp_s` [s]. The ground-truth pose must
/// lie within `max_dt_s` [s] of the stamp, else std::runtime_error.
Eigen::Isometry3d EstimateFrameInWorld(const Trajectory& groundtruth, double first_frame_stamp_s,
                                       const Trajectory& estimated, double max_dt_s);

}  // namespace dslam
