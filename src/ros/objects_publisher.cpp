#include "dslam/ros/objects_publisher.h"

#include <visualization_msgs/MarkerArray.h>

#include "dslam/MovingObjects.h"
#include "dslam/ros/object_conversions.h"

namespace dslam {
namespace ros_layer {

ObjectsPublisher::ObjectsPublisher(ros::NodeHandle& nh, const Config& config)
    : enabled_(config.objects.enabled), objects_(config) {
  if (!enabled_) return;
  objects_pub_ = nh.advertise<dslam::MovingObjects>("moving_objects", 5);
  markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("moving_object_markers", 5);
}

bool ObjectsPublisher::Wanted() const {
  return enabled_ && (objects_pub_.getNumSubscribers() > 0 || markers_pub_.getNumSubscribers() > 0);
}

void ObjectsPublisher::Publish(const RgbdFrame& frame, const FrameResult& result,
                               const std_msgs::Header& odom_header,
                               const Eigen::Isometry3d& T_base_camera) {
  if (!Wanted()) {  // nobody listens: the next subscriber starts with fresh tracks
    if (tracking_) objects_.Reset();
    tracking_ = false;
    return;
  }
  tracking_ = true;
  const dslam::MovingObjects message =
      MakeMovingObjects(objects_.Process(frame, result), T_base_camera, odom_header);
  if (objects_pub_.getNumSubscribers() > 0) objects_pub_.publish(message);
  if (markers_pub_.getNumSubscribers() > 0) markers_pub_.publish(MakeObjectMarkers(message));
}

}  // namespace ros_layer
}  // namespace dslam
