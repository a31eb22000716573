#pragma once
// Publishes the occupancy grid of the static map (BuildOccupancyGrid, part mapping, from the
// StaticMapper's points and rays): nav_msgs/OccupancyGrid `grid` (latched, in the frame of the
// tracker's world data: WorldDataFrameId, map_frame or odom_frame; its origin pose places the
// grid frame, z up, in that frame), rebuilt by a wall-clock timer at grid.rate_hz, only while
// subscribed, only when the map or its transform changed, and with 9 times the last rebuild's
// time between rebuilds (at most 10 % of a core); and the service `save_grid`
// (dslam/SaveGrid) writing map_server's YAML and PGM pair. Up is the published frame's z axis
// (the base frame's, REP 103: the camera mount from TF or the default mount), replaced by the
// normal of the floor when the map shows one (FloorOf).
//
// Threads: the timer and the service run on ROS callback threads, SetWorldFrame on the worker;
// the transform and what was last published are guarded by the MapRevisionGate's mutex, the map
// by the mapper's own. Neither is held together with Slam's map mutex (Slam calls the mapper
// without it).

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <Eigen/Geometry>

#include "dslam/SaveGrid.h"
#include "dslam/core/config.h"
#include "dslam/mapping/occupancy_grid.h"
#include "dslam/mapping/static_mapper.h"
#include "dslam/ros/map_revision_gate.h"
#include "dslam/ros/node_config.h"

namespace dslam {
namespace ros_layer {

/// `grid` as a message in the frame T_frame_world maps the tracker's world to: cell (i, j) at
/// data[j * width + i], the origin the pose of cell (0, 0)'s corner, occupied 100, free 0,
/// unknown -1.
nav_msgs::OccupancyGrid ToMessage(const OccupancyGrid& grid,
                                  const Eigen::Isometry3d& T_frame_world);

/// Owns the grid's topic, timer and service.
class GridPublisher {
 public:
  /// Advertises `grid` and `save_grid` on `nh` (relative names) and starts the timer; `config`:
  /// grid (band, floor, rate, cell size) and map.voxel_size_m (the cell size when grid's is 0).
  GridPublisher(ros::NodeHandle& nh, const NodeConfig& node_config, const Config& config,
                std::shared_ptr<const StaticMapper> mapper);
  /// Stops the timer (waits for a callback in progress).
  ~GridPublisher();

  /// The transform of the tracker's world into the published frame, WorldDataFrame::
  /// T_frame_world [m]. Nothing is published before it is known.
  void SetWorldFrame(const Eigen::Isometry3d& T_frame_world);

 private:
  void OnTimer();
  bool OnSave(dslam::SaveGrid::Request& req, dslam::SaveGrid::Response& res);
  /// The grid of the map now, up the published frame's z axis in the tracker's world.
  OccupancyGrid Build(const Eigen::Isometry3d& T_frame_world) const;

  std::string frame_id_;  ///< WorldDataFrameId(config)
  Config config_;         ///< grid's band, floor and rate; map.voxel_size_m (GridOf)
  std::shared_ptr<const StaticMapper> mapper_;
  ros::Publisher grid_pub_;
  ros::ServiceServer save_srv_;
  ros::WallTimer timer_;
  MapRevisionGate gate_;  ///< the transform and what was last published (own lock)
  /// The timer rebuilds no earlier than this: after a rebuild of t seconds, kIdlePerBuild t later,
  /// so that the grid takes at most 1 / (1 + kIdlePerBuild) of a core (10 %) whatever the map's
  /// size; a grid of the long run's full map (300 keyframes) takes about 0.5 s to build.
  static constexpr double kIdlePerBuild = 9.0;
  ros::WallTime next_rebuild_;
  /// Rebuilds since the last minute's log line: count, summed and longest time [ms] (the timer's
  /// thread only).
  struct RebuildTimes {
    int count = 0;
    double total_ms = 0.0;
    double longest_ms = 0.0;
    ros::WallTime since;
  } rebuilds_;
  /// Adds a rebuild of `ms` and logs the minute's count, mean and longest once a minute.
  void CountRebuild(double ms, const OccupancyGrid& grid);
};

}  // namespace ros_layer
}  // namespace dslam
