#pragma once
// Carrying a pose-graph correction to what hangs off the keyframes: map points and non-keyframe
// poses move rigidly with a reference keyframe. "Uncorrected" is the world estimate before the
// solve, "corrected" the one after; a point or frame attached to keyframe k keeps its pose
// relative to k: X_corrected = T_world_k_corrected T_world_k^-1 X.

#include <map>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/loop_closing/pose_graph.h"

namespace dslam {

/// T_corrected_uncorrected = T_world_keyframe_corrected T_world_keyframe^-1: maps world
/// coordinates [m] of the estimate before the correction to those after it, for anything that
/// moves with the keyframe (poses of the keyframe's optical frame in the world, before and after).
Eigen::Isometry3d KeyFrameCorrection(const Eigen::Isometry3d& T_world_keyframe,
                                     const Eigen::Isometry3d& T_world_keyframe_corrected);

/// A point p_world [m] (world frame, before the correction) moved with its reference keyframe:
/// KeyFrameCorrection(T_world_keyframe, T_world_keyframe_corrected) * p_world.
Eigen::Vector3d CorrectPoint(const Eigen::Vector3d& p_world,
                             const Eigen::Isometry3d& T_world_keyframe,
                             const Eigen::Isometry3d& T_world_keyframe_corrected);

/// The point's world covariance [m^2] after that move: R cov_world R^T with R the rotation of
/// KeyFrameCorrection() (the keyframe's pose is taken as exact).
Eigen::Matrix3d CorrectPointCovariance(const Eigen::Matrix3d& cov_world,
                                       const Eigen::Isometry3d& T_world_keyframe,
                                       const Eigen::Isometry3d& T_world_keyframe_corrected);

/// A frame's pose T_world_camera [m] moved with its reference keyframe:
/// KeyFrameCorrection(T_world_keyframe, T_world_keyframe_corrected) * T_world_camera.
Eigen::Isometry3d CorrectPose(const Eigen::Isometry3d& T_world_camera,
                              const Eigen::Isometry3d& T_world_keyframe,
                              const Eigen::Isometry3d& T_world_keyframe_corrected);

/// CorrectPose() of a non-keyframe (e.g. the current frame, pose T_world_camera before the solve)
/// through its reference keyframe `reference_keyframe_id`, whose pose before the solve is the
/// graph's node and after it the result's. Throws std::invalid_argument naming the id when the
/// graph or the result has no such node.
Eigen::Isometry3d CorrectFramePose(const Eigen::Isometry3d& T_world_camera,
                                   int reference_keyframe_id, const PoseGraph& graph,
                                   const PoseGraphResult& result);

}  // namespace dslam
