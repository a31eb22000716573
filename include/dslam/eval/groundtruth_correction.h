#pragma once
// Ground-truth frame corrections: turning a dataset's motion-capture poses into poses of the colour
// camera's optical frame. Bonn RGB-D Dynamic (Palazzolo et al., IROS 2019) records the pose of the
// motion-capture marker; its documented correction is
//   T_cam = T_ros * T_gt * T_ros * T_m,
// with T_ros = [[-1,0,0,0],[0,0,1,0],[0,1,0,0],[0,0,0,1]] and T_m the marker -> camera offset.
// T_ros is an axis permutation with a sign flip; its 3x3 block has det +1 (a proper rotation by
// 180 deg about (0,1,1)/sqrt(2), not a reflection) and is its own inverse, so T_ros * T_gt * T_ros
// (= T_ros * T_gt * T_ros^-1, a change of world and body axes) is a proper rigid transform.
// T_m's published rotation block is a rotation scaled by ~1.059 (singular values 1.0593, 1.0593,
// 1.0592); it is projected to the nearest rotation (SVD) and its translation kept.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/io/dataset_io.h"
#include "dslam/io/trajectory_io.h"

namespace dslam {

/// The Bonn axis change T_ros as a 4x4 matrix (180 deg rotation about (0,1,1)/sqrt(2); T_ros^2 =
/// I).
Eigen::Matrix4d BonnAxisChange();

/// T_m exactly as published by the Bonn dataset (rotation block not orthonormal).
Eigen::Matrix4d BonnMarkerToCameraRaw();

/// Nearest rotation to `m` in the Frobenius norm: U * diag(1, 1, det(U V^T)) * V^T from the SVD
/// m = U S V^T. Always returns a proper rotation (det +1).
Eigen::Matrix3d NearestRotation(const Eigen::Matrix3d& m);

/// T_m with its rotation block projected by NearestRotation(); translation as published [m].
/// Right-multiplied onto the axis-changed marker pose it gives the camera pose.
Eigen::Isometry3d BonnMarkerToCamera();

/// Camera pose from one Bonn ground-truth (marker) pose: T_ros * T_world_marker * T_ros *
/// BonnMarkerToCamera(). The result is a proper rigid transform (world' <- camera optical frame).
Eigen::Isometry3d BonnCameraPose(const Eigen::Isometry3d& T_world_marker);

/// Applies `correction` to every pose of `groundtruth` (stamps unchanged). kNone returns a copy.
Trajectory ApplyGroundTruthCorrection(const Trajectory& groundtruth,
                                      GroundTruthCorrection correction);

}  // namespace dslam
