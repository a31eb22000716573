#pragma once
// Timestamped camera poses: the trajectory type shared by the pipeline, its readers and writers
// (dslam/io/trajectory_io.h) and its evaluation.

#include <vector>

#include <Eigen/Geometry>

namespace dslam {

/// One timestamped pose T_world_camera.
struct StampedPose {
  double stamp_s = 0.0;                                              ///< [s]
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();  ///< camera -> world [m]
};

/// A time-ordered sequence of poses.
using Trajectory = std::vector<StampedPose>;

}  // namespace dslam
