#pragma once
// Publishes the keyframe map's outputs (keyframe_map_outputs.h): nav_msgs/Path `keyframe_path`
// (every keyframe of the map at its current pose) and visualization_msgs/MarkerArray `loop_edges`
// (the accepted loops), both latched, each only while subscribed and only after a keyframe, a
// new accepted loop or a new subscriber; and keeps loop closing's status fields.
//
// Threads and locks: used by the nodelet's worker thread alone, between frames, holding no lock.
// It reads the map through Slam::ReadMap (the map lock, only to copy the keyframes' ids, stamps and
// poses) and the loops through LoopClosing's getters (its own lock), never one inside the other.

#include <cstdint>
#include <memory>
#include <vector>

#include <ros/ros.h>
#include <std_msgs/Header.h>
#include <Eigen/Geometry>

#include "dslam/backend/slam.h"
#include "dslam/loop_closing/loop_closing.h"
#include "dslam/ros/keyframe_map_outputs.h"

namespace dslam {
namespace ros_layer {

/// [s] Loop closing's status is refreshed at every keyframe and at least this often (it runs on
/// the back-end thread after the keyframe, so a loop is counted at the next refresh).
constexpr double kLoopStatusPeriodS = 1.0;

/// Owns `keyframe_path` and `loop_edges` and the loop status. Call from one thread.
class KeyFrameMapPublisher {
 public:
  /// Advertises the topics on `nh` (the nodelet's node handle, relative names). `slam` must
  /// outlive this object; `loop_closing` is null when loop closing is off (no loops, zeros).
  KeyFrameMapPublisher(ros::NodeHandle& nh, const Slam& slam,
                       std::shared_ptr<const LoopClosing> loop_closing);

  /// Refreshes the loop status when `keyframe` (this frame made one) or kLoopStatusPeriodS
  /// passed since the last refresh; true when the number of accepted loops changed.
  bool RefreshLoopStatus(bool keyframe);

  /// Loop closing's fields for the status message, as of the last refresh.
  const LoopStatus& loop_status() const { return loop_status_; }

  /// Publishes each topic that has subscribers when `changed` (a keyframe was made or the loops
  /// changed) or a subscriber came since its last publication. `header`: the frame's stamp and
  /// the world-data frame (WorldDataFrame::frame_id), into which T_frame_world [m] maps the
  /// tracker's world; T_base_camera [m] is the camera mount.
  void Publish(bool changed, const std_msgs::Header& header, const Eigen::Isometry3d& T_frame_world,
               const Eigen::Isometry3d& T_base_camera);

 private:
  /// True when `publisher` has subscribers and `changed` or more of them than at the last call
  /// (`*subscribers`, updated).
  static bool Due(const ros::Publisher& publisher, bool changed, uint32_t* subscribers);

  const Slam& slam_;
  std::shared_ptr<const LoopClosing> loop_closing_;
  ros::Publisher path_pub_, loops_pub_;
  uint32_t path_subscribers_ = 0, loops_subscribers_ = 0;  ///< at the last Publish
  LoopStatus loop_status_;
  std::vector<LoopKeyFrames> loops_;  ///< accepted loops at the last refresh, oldest first
  ros::WallTime refreshed_;           ///< last refresh of the loop status
};

}  // namespace ros_layer
}  // namespace dslam
