#include "dslam/ros/objects_publisher.h"

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl_conversions/pcl_conversions.h>
#include <sensor_msgs/PointCloud2.h>
#include <visualization_msgs/MarkerArray.h>

#include "dslam/MovingObjects.h"
#include "dslam/ros/object_conversions.h"

namespace dslam {
namespace ros_layer {

ObjectsPublisher::ObjectsPublisher(ros::NodeHandle& nh, const Config& config, WorkerMode mode)
    : enabled_(config.objects.enabled),
      objects_(config),
      obstacle_points_(BackProjection::Of(config.map, config.depth_noise)),
      worker_(enabled_ ? mode : WorkerMode::kSynchronous, 2) {
  if (!enabled_) return;
  objects_pub_ = nh.advertise<dslam::MovingObjects>("moving_objects", 5);
  markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("moving_object_markers", 5);
  obstacles_pub_ = nh.advertise<sensor_msgs::PointCloud2>("obstacles", 5);
}

bool ObjectsPublisher::Wanted() const {
  return enabled_ &&
         (objects_pub_.getNumSubscribers() > 0 || markers_pub_.getNumSubscribers() > 0 ||
          obstacles_pub_.getNumSubscribers() > 0);
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
  if (obstacles_pub_.getNumSubscribers() > 0) {
    PublishObstacles(frame, result, header, T_frame_world);
  }
}

void ObjectsPublisher::PublishObstacles(const RgbdFrame& frame, const FrameResult& result,
                                        const std_msgs::Header& header,
                                        const Eigen::Isometry3d& T_frame_world) {
  pcl::PointCloud<pcl::PointXYZ> points;
  if (result.has_pose) {  // without a pose there is no mask (an empty cloud: nobody known)
    const Eigen::Isometry3f T =
        (T_frame_world * result.T_world_camera).cast<float>();  // optical -> published
    for (const ColouredPoint& point :
         BackProjectMasked(frame, objects_.last_mask(), obstacle_points_)) {
      pcl::PointXYZ q;
      q.getVector3fMap() = T * point.p;
      points.push_back(q);
    }
  }
  sensor_msgs::PointCloud2 message;
  pcl::toROSMsg(points, message);
  message.header = header;
  obstacles_pub_.publish(message);
}

}  // namespace ros_layer
}  // namespace dslam
