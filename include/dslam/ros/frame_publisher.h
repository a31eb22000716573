#pragma once
// Publishes the odometry's per-frame outputs: nav_msgs/Odometry `odom` (continuous, REP 105:
// OdomIntegrator), TF map -> odom and odom -> base, nav_msgs/Path `path` (a bounded ring, at a
// bounded rate), dslam/FrameStatus `status`, and - only when subscribed - the PointClouds
// `static_points` / `dynamic_points`, MarkerArray `graph_edges` and Image `features`.

#include <cstdint>
#include <deque>
#include <string>

#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/Header.h>
#include <tf2_ros/transform_broadcaster.h>
#include <Eigen/Geometry>

#include "dslam/FrameStatus.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/ros/keyframe_map_outputs.h"
#include "dslam/ros/node_config.h"
#include "dslam/ros/odom_integrator.h"
#include "dslam/ros/odom_twist.h"
#include "dslam/tracking/frame_result.h"

namespace dslam {
namespace ros_layer {

/// Counters since the nodelet started, reported in the status message.
struct FrameCounters {
  uint64_t received = 0;   ///< synchronized image sets received
  uint64_t processed = 0;  ///< frames run through the odometry
  uint64_t dropped = 0;    ///< replaced in the queue before processing
  uint64_t rejected = 0;   ///< bad input (encoding, size, camera)
  uint64_t errors = 0;     ///< errors of work off the frame's call (back end, observers, loops)
  double map_lock_max_ms = 0.0;  ///< [ms] longest map-lock hold since the previous frame
};

/// Sets the back-end fields of a FrameStatus message from `backend`: each field of
/// BackEndStatus::Fields() marked kStatusMessage, to the message field of its name
/// (test/ros/status_message_test.cpp checks every pair).
void FillBackEndStatus(const BackEndStatus& backend, dslam::FrameStatus* status);

/// Sets loop closing's fields of a FrameStatus message from `loops`, each to the message field of
/// its name (test/ros/status_message_test.cpp checks them).
void FillLoopStatus(const LoopStatus& loops, dslam::FrameStatus* status);

/// Where the data of the tracker's world (clouds, graph markers, moving objects, static map, path,
/// keyframe path, loop edges) is published for one frame.
struct WorldDataFrame {
  std::string frame_id;  ///< WorldDataFrameId(config): map_frame or odom_frame
  /// [m] Maps points of the tracker's world (the first frame's optical frame) into frame_id:
  /// T_base_camera into the map frame; T_base_camera * T_map_odom^-1 (OdomIntegrator, optical
  /// frames) into odom.
  Eigen::Isometry3d T_frame_world = Eigen::Isometry3d::Identity();
};

/// Owns the output publishers of the odometry nodelet and the odom pose. Call from one thread.
class FramePublisher {
 public:
  /// Advertises the outputs on `nh` (the nodelet's node handle, relative names).
  FramePublisher(ros::NodeHandle& nh, const NodeConfig& config);

  /// Publishes everything for one processed frame, after adding its pose to the odom pose.
  /// `header` carries the image stamp and the camera's optical frame id; T_base_camera is the
  /// camera mount [m]; latency_ms is the wall time from receiving the images.
  void Publish(const FrameResult& result, const RgbdFrame& frame, const std_msgs::Header& header,
               const Eigen::Isometry3d& T_base_camera, const FrameCounters& counters,
               double latency_ms);

  /// Publishes the status of a set that never reached the odometry (bad input, a skipped
  /// stamp): state "rejected", no pose, `problem` as the message.
  void PublishRejected(const std::string& problem, const std_msgs::Header& header,
                       const FrameCounters& counters, double latency_ms);

  /// Loop closing's status, reported by every status message from now on.
  void SetLoopStatus(const LoopStatus& loops) { loops_ = loops; }

  /// The odometry started a new run at the origin (time went backwards): empties the path and
  /// restarts odom and map -> odom at the identity.
  void StartNewRun() {
    path_.clear();
    odom_.Restart();
    twist_.Restart();
  }

  /// Where the data of the tracker's world goes for the frame last published, with the camera
  /// mount T_base_camera [m].
  WorldDataFrame WorldData(const Eigen::Isometry3d& T_base_camera) const;

  /// The odometry's per-frame lists someone will see (FrameRequest): points for the clouds and
  /// the feature image, edges for the graph markers.
  bool WantsPoints() const;
  bool WantsEdges() const;

 private:
  /// `odom` and the TF of the odom pose (odom_), map -> odom with publish_map_tf.
  void PublishOdom(const FrameResult& result, const std_msgs::Header& odom_header,
                   const Eigen::Isometry3d& T_base_camera);
  /// Appends to the ring of path poses; publishes it at most at path_rate_hz when subscribed.
  void UpdatePath(const geometry_msgs::PoseStamped& pose);
  /// `state`: FrameStatus.state (the tracking state, or "rejected").
  void PublishStatus(const FrameResult& result, const std::string& state,
                     const std_msgs::Header& odom_header, const FrameCounters& counters,
                     double latency_ms);
  /// `world_header`: image stamp, world.frame_id.
  void PublishVisuals(const FrameResult& result, const RgbdFrame& frame,
                      const std_msgs::Header& header, const std_msgs::Header& world_header,
                      const Eigen::Isometry3d& T_frame_world);

  NodeConfig config_;
  ros::Publisher odom_pub_, path_pub_, status_pub_;
  ros::Publisher static_pub_, dynamic_pub_, edges_pub_, features_pub_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  OdomIntegrator odom_;                          ///< the continuous odom pose and map -> odom
  OdomTwist twist_;                              ///< odom's twist: the base's velocity
  std::deque<geometry_msgs::PoseStamped> path_;  ///< at most path_max_poses, oldest first
  ros::WallTime path_published_;                 ///< last publication of the path
  LoopStatus loops_;                             ///< SetLoopStatus
};

}  // namespace ros_layer
}  // namespace dslam
