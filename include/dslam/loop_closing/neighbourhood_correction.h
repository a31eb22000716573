#pragma once
// The step before the pose graph in ORB-SLAM2's LoopClosing::CorrectLoop: once a loop gives the
// current keyframe a corrected pose, its neighbourhood (its covisible keyframes) moves rigidly
// with it, and those poses are the solve's initial guesses; the edges keep the measurements of
// the poses before the correction.

#include <map>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/loop_closing/pose_graph.h"

namespace dslam {

/// Corrected poses T_world_camera [m] of keyframe `current_id` and of each keyframe in
/// `neighbourhood` (ids; the current one may be among them), by id: the current keyframe's is
/// `T_world_current_corrected`, each neighbour's T_world_current_corrected T_world_current^-1
/// T_world_neighbour with the poses before the correction taken from the graph's nodes (the
/// neighbours keep their poses relative to the current keyframe). Throws std::invalid_argument
/// naming the id when the graph has no such node.
std::map<int, Eigen::Isometry3d> CorrectLoopNeighbourhood(
    const PoseGraph& graph, int current_id, const Eigen::Isometry3d& T_world_current_corrected,
    const std::vector<int>& neighbourhood);

/// Sets the pose of each node named in `T_world_camera` (by id, [m]) to the given one: the
/// initial guesses of OptimisePoseGraph. Edges and `fixed` flags are left as they are. Throws
/// std::invalid_argument naming the id when the graph has no such node (then nothing changed).
void SetInitialGuesses(const std::map<int, Eigen::Isometry3d>& T_world_camera, PoseGraph* graph);

}  // namespace dslam
