#include "dslam/ros/objects_publisher.h"

#include <visualization_msgs/MarkerArray.h>

#include "dslam/MovingObjects.h"
#include "dslam/ros/object_conversions.h"

namespace dslam {
namespace ros_layer {

ObjectsPublisher::ObjectsPublisher(ros::NodeHandle& nh, const Config& config, WorkerMode mode)
    : enabled_(config.objects.enabled),
      objects_(config),
      worker_(enabled_ ? mode : WorkerMode::kSynchronous, 2) {
  if (!enabled_) return;
  objects_pub_ = nh.advertise<dslam::MovingObjects>("moving_objects", 5);
  markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("moving_object_markers", 5);
}

bool ObjectsPublisher::Wanted() const {
  return enabled_ && (objects_pub_.getNumSubscribers() > 0 || markers_pub_.getNumSubscribers() > 0);
}

void ObjectsPublisher::Publish(const RgbdFrame& frame, const FrameResult& result,
                               const std_msgs::Header& header,
                               const Eigen::Isometry3d& T_frame_world) {
  if (!Wanted()) {  // nobody listens: the next subscriber starts with fresh tracks
    if (tracking_) worker_.Post([this] { objects_.Reset(); });
    tracking_ = false;
    return;
  }
  tracking_ = true;
  worker_.Post([this, frame, result, header, T_frame_world] {
    try {
      TrackAndPublish(frame, result, header, T_frame_world);
    } catch (const std::exception& e) {  // the next frames are still tracked
      ROS_ERROR_THROTTLE(1.0, "dslam: moving objects of a frame skipped: %s", e.what());
    }
  });
}

void ObjectsPublisher::TrackAndPublish(const RgbdFrame& frame, const FrameResult& result,
                                       const std_msgs::Header& header,
                                       const Eigen::Isometry3d& T_frame_world) {
  const dslam::MovingObjects message =
      MakeMovingObjects(objects_.Process(frame, result), T_frame_world, header);
  if (objects_pub_.getNumSubscribers() > 0) objects_pub_.publish(message);
  if (markers_pub_.getNumSubscribers() > 0) markers_pub_.publish(MakeObjectMarkers(message));
}

}  // namespace ros_layer
}  // namespace dslam
