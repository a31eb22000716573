#pragma once
// Publishes the moving objects of each frame: dslam/MovingObjects `moving_objects`, the
// MarkerArray `moving_object_markers` (object_conversions.h) and the PointCloud2 `obstacles` (the
// depth of the frame's dynamic-mask pixels: the people in view now, fields x y z, for a costmap's
// obstacle layer), in the frame of the tracker's world data (WorldDataFrame: map_frame, or
// odom_frame without publish_map_tf), stamped with the frame. The dynamic mask and the tracker
// (part mapping, MovingObjectTracker) run after Slam::ProcessFrame, only while objects.enabled
// and someone subscribes to any of the topics (a new subscriber starts with
// fresh tracks): threaded (~backend_threads), on an OrderedWorker thread of their own that takes
// the frames in order (the odometry's worker only hands each frame over; it waits while two
// frames are queued); otherwise on the odometry's worker thread. The tracker and the publishers'
// messages are the objects thread's alone (OrderedWorker's locking policy).

#include <memory>

#include <ros/ros.h>
#include <std_msgs/Header.h>
#include <Eigen/Geometry>

#include "dslam/core/config.h"
#include "dslam/core/ordered_worker.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/mapping/coloured_cloud.h"
#include "dslam/mapping/moving_object_tracker.h"
#include "dslam/tracking/frame_result.h"

namespace dslam {
namespace ros_layer {

/// Owns the moving-object publishers, the tracker and its thread. Call from one thread (the
/// odometry's worker).
class ObjectsPublisher {
 public:
  /// Advertises the topics on `nh` (relative names) when config.objects.enabled; `mode` says
  /// where the tracker runs (kThreaded: its own thread, started only when enabled).
  ObjectsPublisher(ros::NodeHandle& nh, const Config& config, WorkerMode mode);

  /// True when the next frame's objects will be computed: the odometry must then fill
  /// FrameResult::points (FrameRequest).
  bool Wanted() const;

  /// Tracks the objects of `frame` (its `result`) and publishes them with `header` (image stamp,
  /// WorldDataFrame::frame_id), mapped from the tracker's world by T_frame_world [m]. Threaded,
  /// queues the frame (its images shared, not copied) and returns, after waiting while two
  /// frames are queued.
  void Publish(const RgbdFrame& frame, const FrameResult& result, const std_msgs::Header& header,
               const Eigen::Isometry3d& T_frame_world);

  /// Errors of the tracker's work (its OrderedWorker), each reported once.
  ErrorLog& errors() const { return worker_.errors(); }

 private:
  /// The objects thread's part of Publish.
  void TrackAndPublish(const RgbdFrame& frame, const FrameResult& result,
                       const std_msgs::Header& header, const Eigen::Isometry3d& T_frame_world);

  /// The people's points of the frame just tracked (objects_.last_mask()) as `obstacles`.
  void PublishObstacles(const RgbdFrame& frame, const FrameResult& result,
                        const std_msgs::Header& header, const Eigen::Isometry3d& T_frame_world);

  bool enabled_;
  bool tracking_ = false;  ///< the tracker was handed the previous frame (the caller's)
  MovingObjectTracker objects_;
  const BackProjection obstacle_points_;  ///< the static map's sampling (BackProjection::Of)
  ros::Publisher objects_pub_, markers_pub_, obstacles_pub_;
  OrderedWorker worker_;  ///< last: its destructor runs the queued frames before the above go
};

}  // namespace ros_layer
}  // namespace dslam
