#pragma once
// Publishes the static map (StaticMapper, part mapping, fed by Slam as a keyframe observer):
// sensor_msgs/PointCloud2 `static_map` (latched, fields x y z rgb, in the frame of the tracker's
// world data: WorldDataFrameId, map_frame or odom_frame), rebuilt by a wall-clock timer at
// static_map_rate_hz, only while subscribed and only when the map or its transform changed; the
// service `save_map` (dslam/SaveMap) writing a PCD file in the tracker's world frame, and
// `save_octomap` (dslam/SaveMap: `points` the occupied leaves) writing the map as an OctoMap
// binary file (octomap_file.h) in the same frame.
//
// Threads: the timer and the service run on ROS callback threads, SetWorldFrame on the worker;
// the transform and what was last published are guarded by the MapRevisionGate's mutex, the map
// by the mapper's own. Neither is held together with Slam's map mutex (Slam calls the mapper
// without it).

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>

#include <ros/ros.h>
#include <Eigen/Geometry>

#include "dslam/SaveMap.h"
#include "dslam/mapping/static_mapper.h"
#include "dslam/ros/map_revision_gate.h"
#include "dslam/ros/node_config.h"

namespace dslam {
namespace ros_layer {

/// Owns the static map's topic, timer and service.
class StaticMapPublisher {
 public:
  /// Advertises `static_map`, `save_map` and `save_octomap` on `nh` (relative names) and starts
  /// the timer.
  /// `voxel_size_m` [m]: the map's voxel (map.voxel_size_m), the OctoMap's leaf.
  StaticMapPublisher(ros::NodeHandle& nh, const NodeConfig& config,
                     std::shared_ptr<const StaticMapper> mapper, double voxel_size_m);
  /// Stops the timer (waits for a callback in progress).
  ~StaticMapPublisher();

  /// The transform of the tracker's world into the published frame, WorldDataFrame::
  /// T_frame_world [m] (the camera mount into the map frame, the base at the first frame:
  /// p_map = T_base_camera * p_world). Nothing is published before it is known.
  void SetWorldFrame(const Eigen::Isometry3d& T_frame_world);

 private:
  void OnTimer();
  bool OnSave(dslam::SaveMap::Request& req, dslam::SaveMap::Response& res);
  bool OnSaveOctoMap(dslam::SaveMap::Request& req, dslam::SaveMap::Response& res);

  std::string frame_id_;  ///< WorldDataFrameId(config)
  std::shared_ptr<const StaticMapper> mapper_;
  ros::Publisher map_pub_;
  ros::ServiceServer save_srv_, save_octomap_srv_;
  double voxel_size_m_;  ///< [m] map.voxel_size_m: the OctoMap's leaves
  ros::WallTimer timer_;
  MapRevisionGate gate_;  ///< the transform and what was last published (own lock)
};

}  // namespace ros_layer
}  // namespace dslam
