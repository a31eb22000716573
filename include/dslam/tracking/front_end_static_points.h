#pragma once
// Front-end static point determination (paper Sec. V-A "Determination of Static Points by the
// Front End"): after the initial pose, the tracked points with depth (marked and unmarked, so a
// wrongly unmarked point can be re-marked) form a Delaunay graph whose edges are checked against
// point-correlation measurements of the current and reference frames; points in other
// components with evidence against the static one lose their mark.
//
// Which frames: the paper compares the previous frame with the current one. At 30 Hz that
// baseline is too short to see walking people (edge changes are the size of the depth noise;
// window settings compared in docs/benchmarks/static-points.md), so by default ("keyframes") the
// current frame is compared with up to `front_end_keyframes` keyframes spread over the local
// window, in which the points were measured when the keyframe was made: the baseline is then up to
// the window's time span. Measurements of one frame share that frame's pose, so only each frame's
// rotation enters z_ijk = y_ik - y_jk (translation cancels) and drift between keyframes cannot fake
// inconsistency. "previous" is the paper's choice and "both" uses the keyframes and the previous
// frame.

#include <vector>

#include "dslam/core/config.h"
#include "dslam/core/depth_uncertainty.h"
#include "dslam/static_points/static_points.h"
#include "dslam/tracking/local_map_matching.h"

namespace dslam {

/// Output of the front end: the determination's result and which matches it covered.
struct FrontEndStaticPoints {
  StaticPointsResult result;
  std::vector<int> graph_match;  ///< per graph point: index into the frame's matches
  bool ran = false;              ///< false when too few points had the needed measurements
};

/// The graph of the front end's determination: it needs the matches, not the frame's pose, so it
/// can be built while the initial pose is solved.
struct FrontEndGraph {
  std::vector<int> usable;  ///< matches with a map point and a depth measurement
  std::vector<int> chosen;  ///< indices into `usable`: the graph's points, increasing
  std::vector<Eigen::Vector3d> points_world;  ///< [m] p_world of the chosen points, in order
  std::vector<GraphEdge> edges;               ///< Delaunay graph over points_world
  double graph_ms = 0.0;  ///< [ms] time to choose the points and build the graph
};

/// The graph over the usable matches (fewer than kMinGraphPoints: no points, no edges);
/// with more than config.max_graph_points, over the subset described at
/// DetermineStaticPointsFrontEnd.
FrontEndGraph BuildFrontEndGraph(const Map& map, const std::vector<PointMatch>& matches,
                                 const FrameFeatures& features, const StaticPointsConfig& config);

/// Builds the problem over the matched points with a depth measurement in the current
/// frame (pose `T_camera_world`) and their measurements in `reference_frames` (keyframes and/or
/// the previous frame, chosen by the caller), runs DetermineStaticPoints and returns the result.
/// With fewer than kMinGraphPoints such points nothing runs (`ran` stays false). With
/// more than config.max_graph_points (when > 0) the graph is built over that many: every unsettled
/// point (unmarked, or a candidate) and verified static points spread evenly over the image for the
/// rest (SpatiallyEvenSubset); the others follow in graph_match / result.labels with their
/// nearest graph point's label (NearestGraphPoints, InheritedLabel) and have no edges.
FrontEndStaticPoints DetermineStaticPointsFrontEnd(
    const Map& map, const std::vector<PointMatch>& matches, const FrameFeatures& features,
    const Eigen::Isometry3d& T_camera_world,
    const std::vector<const FrameMeasurements*>& reference_frames,
    const StaticPointsConfig& config);

/// The same with the graph built beforehand by BuildFrontEndGraph on the same map, matches and
/// features.
FrontEndStaticPoints DetermineStaticPointsFrontEnd(
    const Map& map, const std::vector<PointMatch>& matches, const FrameFeatures& features,
    const Eigen::Isometry3d& T_camera_world,
    const std::vector<const FrameMeasurements*>& reference_frames, const StaticPointsConfig& config,
    FrontEndGraph graph);

/// How labels turn into marks (from TrackingConfig).
struct LabelRules {
  int isolated_frames_to_unmark = 3;  ///< [frames] isolated this often in a row: unmarked
  int verify_frames = 6;              ///< [frames] a candidate is verified once static this late
  int remark_frames = 15;             ///< [frames] at most this many static frames to re-mark
};

/// Applies the labels (nothing changes when no static component was chosen):
/// - dynamic (a member of another component: a group of points that moved together) -> unmarked;
/// - isolated (every edge inconsistent): most often a false match rather than a moving point, so
///   the match is only excluded from this frame's pose; a point isolated in
///   `rules.isolated_frames_to_unmark` consecutive frames is unmarked;
/// - static -> isolation count cleared; an unmarked point is marked again once it was static in
///   as many consecutive frames as it had been labelled dynamic, at most `rules.remark_frames`;
///   a marked candidate (new point) becomes verified once it is static at least
///   `rules.verify_frames` after its creation (frame `frame_index` now).
/// A frozen point (Map::Freeze) keeps its marks; a dynamic or isolated label still excludes it.
/// Returns, parallel to `matches`, whether each match must stay out of the pose.
std::vector<bool> ApplyStaticLabels(const FrontEndStaticPoints& front_end,
                                    const std::vector<PointMatch>& matches, const LabelRules& rules,
                                    int frame_index, Map* map);

}  // namespace dslam
