#pragma once
// Publishes the occupancy grid of the static map (BuildOccupancyGrid, part mapping, from the
// StaticMapper's points and rays): nav_msgs/OccupancyGrid `grid` (latched, in the frame of the
// tracker's world data: WorldDataFrameId, map_frame or odom_frame; its origin pose places the
// grid frame, z up, in that frame), rebuilt at grid.rate_hz, only while subscribed, only when the
// map or its transform changed, with 9 times the last rebuild's time between rebuilds (at most
// 10 % of a core), built on a thread of its own that runs only when a core would otherwise idle
// (Linux SCHED_IDLE: tracking and the back end never wait for a core because of it); and the service
// `save_grid`
// (dslam/SaveGrid) writing map_server's YAML and PGM pair. Up is the published frame's z axis
// (the base frame's, REP 103: the camera mount from TF or the default mount), replaced by the
// normal of the floor when the map shows one (FloorOf).
//
// Threads: the timer and the service run on ROS callback threads, SetWorldFrame on the worker.
// The timer copies the map's points and rays (StaticMapper::Rays, at the timer's priority, under
// the mapper's mutex) and hands them to the builder thread; the builder takes no lock but
// built_mutex_ (to hand the grid back), so that at idle priority it never holds a lock a busy
// thread waits for (ROS's publishers and logging included): the timer publishes and logs what it
// built at its next tick (every kPollS at most). The transform and what was last published are
// guarded by the MapRevisionGate's mutex; next_rebuild_ and rebuilds_ are the timer thread's.
// None is held together with Slam's map mutex (Slam calls the mapper without it).

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
#include "dslam/core/ordered_worker.h"
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
  /// Stops the timer (waits for a callback in progress), then the builder (after the grid it is
  /// building).
  ~GridPublisher();

  /// The transform of the tracker's world into the published frame, WorldDataFrame::
  /// T_frame_world [m]. Nothing is published before it is known.
  void SetWorldFrame(const Eigen::Isometry3d& T_frame_world);

 private:
  /// Publishes what the builder finished, then hands it a rebuild when one is due and it is
  /// idle.
  void OnTimer();
  /// Publishes and counts the grid the builder finished, if any (timer thread).
  void PublishBuilt();
  bool OnSave(dslam::SaveGrid::Request& req, dslam::SaveGrid::Response& res);
  /// The grid of `rays`, up the published frame's z axis in the tracker's world.
  OccupancyGrid Build(const StaticMapRays& rays, const Eigen::Isometry3d& T_frame_world) const;
  /// Adds a rebuild of `copy_ms` + `ms` and logs the minute's count, means and longest once a
  /// minute.
  void CountRebuild(double copy_ms, double ms, const OccupancyGrid& grid);

  std::string frame_id_;  ///< WorldDataFrameId(config)
  Config config_;         ///< grid's band, floor and rate; map.voxel_size_m (GridOf)
  std::shared_ptr<const StaticMapper> mapper_;
  ros::Publisher grid_pub_;
  ros::ServiceServer save_srv_;
  ros::WallTimer timer_;
  /// [s] The timer's longest period: a finished grid waits at most this long to be published.
  static constexpr double kPollS = 0.1;
  MapRevisionGate gate_;  ///< the transform and what was last published (own lock)
  /// The timer hands no rebuild before this: 1 / grid.rate_hz after the last one started, and
  /// kIdlePerBuild times the last one's copy and build time after it was published, so that the
  /// grid takes at most 1 / (1 + kIdlePerBuild) of a core (10 %) whatever the map's size; a grid
  /// of the long run's full map (300 keyframes) takes about 0.5 s to build.
  static constexpr double kIdlePerBuild = 9.0;
  ros::WallTime next_rebuild_;
  /// Rebuilds since the last minute's log line: count, summed copy and build times and the
  /// longest build [ms] (wall time: the builder's includes time preempted).
  struct RebuildTimes {
    int count = 0;
    double copy_total_ms = 0.0;
    double total_ms = 0.0;
    double longest_ms = 0.0;
    ros::WallTime since;
  } rebuilds_;
  /// A grid the builder finished (or its error), with the copy and build times [ms].
  struct Built {
    std::optional<OccupancyGrid> grid;
    Eigen::Isometry3d T_frame_world;
    double copy_ms = 0.0;
    double build_ms = 0.0;
    std::string error;
  };
  std::mutex built_mutex_;      ///< guards built_
  std::optional<Built> built_;  ///< set by the builder, taken by PublishBuilt
  /// The builder's: set by its first task (before it sets built_); the timer reads them after
  /// taking a built_.
  bool builder_idle_priority_ = false;
  std::string idle_priority_problem_;  ///< why SCHED_IDLE was refused; empty when it was not
  bool idle_priority_logged_ = false;  ///< the timer's
  /// Builds one grid at a time, at idle priority. Declared last: destroyed (joined) first.
  OrderedWorker builder_{WorkerMode::kThreaded, 1, nullptr, "grid builder"};
};

}  // namespace ros_layer
}  // namespace dslam
