#pragma once
// Publishes the static map (StaticMapper, part mapping, fed by Slam as a keyframe observer):
// sensor_msgs/PointCloud2 `static_map` (latched, in the odom frame, fields x y z rgb), rebuilt by
// a wall-clock timer at static_map_rate_hz, only while subscribed and only when the map changed;
// and the service `save_map` (dslam/SaveMap) writing a PCD file in the odometry world frame.
//
// Threads: the timer and the service run on ROS callback threads, SetMount on the worker; the
// mount and the last published revision are guarded by this class's mutex, the map by the
// mapper's own. Neither is held together with Slam's map mutex (Slam calls the mapper without it).

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>

#include <ros/ros.h>
#include <Eigen/Geometry>

#include "dslam/SaveMap.h"
#include "dslam/mapping/static_mapper.h"
#include "dslam/ros/node_config.h"

namespace dslam {
namespace ros_layer {

/// Owns the static map's topic, timer and service.
class StaticMapPublisher {
 public:
  /// Advertises `static_map` and `save_map` on `nh` (relative names) and starts the timer.
  StaticMapPublisher(ros::NodeHandle& nh, const NodeConfig& config,
                     std::shared_ptr<const StaticMapper> mapper);
  /// Stops the timer (waits for a callback in progress).
  ~StaticMapPublisher();

  /// The camera mount T_base_camera [m] (the odom frame is the base frame at the first frame:
  /// p_odom = T_base_camera * p_world). Nothing is published before it is known.
  void SetMount(const Eigen::Isometry3d& T_base_camera);

 private:
  void OnTimer();
  bool OnSave(dslam::SaveMap::Request& req, dslam::SaveMap::Response& res);

  std::string odom_frame_;
  std::shared_ptr<const StaticMapper> mapper_;
  ros::Publisher map_pub_;
  ros::ServiceServer save_srv_;
  ros::WallTimer timer_;
  std::mutex mutex_;                                ///< guards the two members below
  std::optional<Eigen::Isometry3d> T_base_camera_;  ///< set by the worker
  std::optional<uint64_t> published_revision_;      ///< of the last message sent
};

}  // namespace ros_layer
}  // namespace dslam
