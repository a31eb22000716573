#pragma once
// The node's outputs of the keyframe map, built from plain copies so that they are testable
// without a node: the corrected keyframe path (`keyframe_path`), the accepted loops as rviz lines
// (`loop_edges`), loop closing's fields of the status message, and the current segment of the
// refined trajectory (`save_refined_trajectory`). KeyFrameMapPublisher (keyframe_map_publisher.h)
// and the nodelet's service use them.

#include <vector>

#include <nav_msgs/Path.h>
#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>
#include <Eigen/Geometry>

#include "dslam/core/trajectory.h"
#include "dslam/loop_closing/loop_closing.h"
#include "dslam/tracking/map.h"

namespace dslam {
namespace ros_layer {

/// A keyframe of the map at its current pose, copied out under the map lock.
struct KeyFrameView {
  int id = -1;           ///< KeyFrame::id
  double stamp_s = 0.0;  ///< [s] KeyFrame::stamp_s
  /// [m] the keyframe's colour optical frame -> the tracker's world, as the map holds it now
  /// (after local BA and loop corrections)
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
};

/// Every keyframe of `map` (window and archive, Map::AllKeyFrames), oldest first. The one step
/// that reads the map: call it inside Slam::ReadMap and build the messages after releasing it.
std::vector<KeyFrameView> KeyFrameViews(const Map& map);

/// The base's pose at each keyframe, oldest first: T_frame_world * T_world_camera *
/// T_base_camera^-1 [m] (as `path` gives the base's pose of each frame), each stamped with its
/// keyframe's stamp and `header.frame_id`; the path's header is `header`.
nav_msgs::Path MakeKeyFramePath(const std::vector<KeyFrameView>& keyframes,
                                const Eigen::Isometry3d& T_frame_world,
                                const Eigen::Isometry3d& T_base_camera,
                                const std_msgs::Header& header);

/// An accepted loop by its two keyframes (LoopDetection's ids).
struct LoopKeyFrames {
  int query_id = -1;  ///< the newer keyframe, which recognised the place
  int match_id = -1;  ///< the older keyframe of the same place
};

/// The keyframes of each loop in `loops`, in the same order.
std::vector<LoopKeyFrames> LoopKeyFramesOf(const std::vector<ClosedLoop>& loops);

/// One LINE_LIST marker (namespace "loops", id 0, header `header`, orange, 2 cm wide): per loop a
/// line from the query keyframe's camera centre to the match keyframe's, both at their poses in
/// `keyframes` mapped by T_frame_world [m]. A loop whose keyframe is not in `keyframes` (erased
/// since, or before a reset) is left out; with no line the marker is a DELETE, so that rviz drops
/// the lines it showed.
visualization_msgs::MarkerArray MakeLoopEdgeMarkers(const std::vector<LoopKeyFrames>& loops,
                                                    const std::vector<KeyFrameView>& keyframes,
                                                    const Eigen::Isometry3d& T_frame_world,
                                                    const std_msgs::Header& header);

/// Loop closing's fields of FrameStatus; all zero without loop closing.
struct LoopStatus {
  int loop_closures = 0;   ///< [-] loops accepted since the node started (resets included)
  int loop_keyframes = 0;  ///< [-] keyframes loop closing has processed since the node started
  /// [ms] loop closing's time for the newest of them (detection, and the correction when it
  /// closed a loop)
  double loop_ms = 0.0;
};

/// LoopStatus of what loop closing has done (LoopClosing::work).
LoopStatus SummariseLoops(const LoopWork& work);

/// The current trajectory segment of `poses` (Slam::RefinedPoses: every tracked frame of the
/// node's run in order, all segments): of the last run of non-decreasing stamps (a segment ends
/// where time went backwards), the poses stamped at or after `first_stamp_s` [s], the current
/// segment's first tracked frame (which also drops an older segment whose last stamps the new one
/// did not go below). Empty when none is.
Trajectory CurrentSegment(const Trajectory& poses, double first_stamp_s);

}  // namespace ros_layer
}  // namespace dslam
