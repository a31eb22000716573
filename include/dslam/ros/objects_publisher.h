#pragma once
// Publishes the moving objects of each frame: dslam/MovingObjects `moving_objects` and the
// MarkerArray `moving_object_markers` (object_conversions.h), in the odom frame. The dynamic
// mask and the tracker (part mapping, MovingObjectTracker) run on the worker thread after
// Slam::ProcessFrame, only while objects.enabled and someone subscribes to either topic (a new
// subscriber starts with fresh tracks).

#include <memory>

#include <ros/ros.h>
#include <std_msgs/Header.h>
#include <Eigen/Geometry>

#include "dslam/core/config.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/mapping/moving_object_tracker.h"
#include "dslam/tracking/frame_result.h"

namespace dslam {
namespace ros_layer {

/// Owns the moving-object publishers and the tracker. Call from one thread (the worker).
class ObjectsPublisher {
 public:
  /// Advertises the topics on `nh` (relative names) when config.objects.enabled.
  ObjectsPublisher(ros::NodeHandle& nh, const Config& config);

  /// True when the next frame's objects will be computed: the odometry must then fill
  /// FrameResult::points (FrameRequest).
  bool Wanted() const;

  /// Tracks the objects of `frame` (its `result`) and publishes them with `odom_header` (image
  /// stamp, odom frame id); T_base_camera is the camera mount [m].
  void Publish(const RgbdFrame& frame, const FrameResult& result,
               const std_msgs::Header& odom_header, const Eigen::Isometry3d& T_base_camera);

 private:
  bool enabled_;
  bool tracking_ = false;  ///< the tracker saw the previous frame
  MovingObjectTracker objects_;
  ros::Publisher objects_pub_, markers_pub_;
};

}  // namespace ros_layer
}  // namespace dslam
