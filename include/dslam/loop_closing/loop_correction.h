#pragma once
// Loop correction (issue 33 item 3): the keyframe map's pose graph for a verified loop, and the
// corrected keyframe poses it gives. Nodes are every keyframe of the map (window and archive) at
// its current pose; edges, measured from the current poses, are the spanning tree (each keyframe
// to the one made before it) and covisibility (keyframes that observe at least
// kCovisibilityEdgePoints map points in common: ORB-SLAM2's essential graph uses 100); the
// loop edge carries the verified relative pose. The oldest keyframe is fixed. Every edge measured
// from the current poses is satisfied before the solve, so the loop edge's disagreement alone is
// spread over the chain, by the edges' sigmas.

#include <map>

#include <Eigen/Geometry>

#include "dslam/loop_closing/pose_graph.h"
#include "dslam/tracking/map.h"

namespace dslam {

constexpr int kCovisibilityEdgePoints = 100;  ///< shared points of a covisibility edge
constexpr double kOdometryEdgeSigmaM = 0.01;  ///< [m] spanning-tree and covisibility edges
constexpr double kOdometryEdgeSigmaRad = 0.0035;  ///< [rad] (0.2 deg)
constexpr double kLoopEdgeSigmaM = 0.005;         ///< [m] the loop edge
constexpr double kLoopEdgeSigmaRad = 0.0017;      ///< [rad] (0.1 deg)

/// The pose graph of `map`'s keyframes (as at the top of this file) with the loop edge from
/// `match_keyframe_id` to `query_keyframe_id` measuring T_match_query [m] (query camera in the
/// match keyframe's camera frame). Throws std::invalid_argument when either keyframe is missing.
PoseGraph BuildLoopPoseGraph(const Map& map, int match_keyframe_id, int query_keyframe_id,
                             const Eigen::Isometry3d& T_match_query);

/// [m] T_world_camera of every keyframe after optimising `graph`; empty when the solve failed.
std::map<int, Eigen::Isometry3d> CorrectedKeyFramePoses(const PoseGraph& graph,
                                                        const PoseGraphOptions& options = {});

}  // namespace dslam
