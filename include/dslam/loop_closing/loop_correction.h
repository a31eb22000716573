#pragma once
// Loop correction (issue 33 item 3): the keyframe map's pose graph for a verified loop, and the
// corrected keyframe poses it gives. Nodes are every keyframe of the map (window and archive) at
// its current pose; edges, measured from the current poses, are the spanning tree (each keyframe
// to the one made before it) and covisibility (keyframes that observe at least
// kCovisibilityEdgePoints map points in common: ORB-SLAM2's essential graph uses 100); the
// loop edge carries the verified relative pose. Spanning edges over a weak episode get
// kWeakEdgeSigmaScale times the sigmas. The oldest keyframe is fixed. Every edge measured
// from the current poses is satisfied before the solve, so the loop edge's disagreement alone is
// spread over the chain, by the edges' sigmas.

#include <map>
#include <vector>

#include <Eigen/Geometry>

#include "dslam/loop_closing/pose_graph.h"
#include "dslam/tracking/map.h"

namespace dslam {

constexpr int kCovisibilityEdgePoints = 100;  ///< shared points of a covisibility edge
constexpr double kOdometryEdgeSigmaM = 0.01;  ///< [m] spanning-tree and covisibility edges
constexpr double kOdometryEdgeSigmaRad = 0.0035;  ///< [rad] (0.2 deg)
/// Factor on the spanning-tree edge sigmas of a keyframe whose motion from the previous one rests
/// on a weak episode (KeyFrame::weak_since_previous): where people covered the view, the pose
/// can jump (docs/benchmarks/loop-closing.md, "Issue 33, part 1"), and the loop's error belongs
/// there.
constexpr double kWeakEdgeSigmaScale = 10.0;
constexpr double kLoopEdgeSigmaM = 0.005;         ///< [m] the loop edge
constexpr double kLoopEdgeSigmaRad = 0.0017;      ///< [rad] (0.1 deg)

/// A loop edge: keyframe `query_keyframe_id` seen again in `match_keyframe_id`.
struct LoopEdge {
  int match_keyframe_id = -1;
  int query_keyframe_id = -1;
  /// [m] query camera in the match keyframe's camera frame, as verified
  Eigen::Isometry3d T_match_query = Eigen::Isometry3d::Identity();
};

/// The pose graph of `map`'s keyframes (as at the top of this file) with a loop edge for each of
/// `loops` whose keyframes are both in the map (the newest loop and the ones accepted before it,
/// so that a new loop does not undo an older one). Throws std::invalid_argument when the last of
/// `loops` (the new one) names a keyframe the map does not have.
PoseGraph BuildLoopPoseGraph(const Map& map, const std::vector<LoopEdge>& loops);

/// [m] T_world_camera of every keyframe after optimising `graph`; empty when the solve failed.
std::map<int, Eigen::Isometry3d> CorrectedKeyFramePoses(const PoseGraph& graph,
                                                        const PoseGraphOptions& options = {});

}  // namespace dslam
