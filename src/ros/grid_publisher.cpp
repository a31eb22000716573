#include "dslam/ros/grid_publisher.h"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "dslam/ros/service_reply.h"

namespace dslam {
namespace ros_layer {
namespace {

/// Makes the calling thread run only when a core would otherwise be idle (Linux SCHED_IDLE,
/// sched(7)); returns the error's text, empty on success.
std::string RunThisThreadWhenIdle() {
  sched_param param{};
  param.sched_priority = 0;
  const int error = pthread_setschedparam(pthread_self(), SCHED_IDLE, &param);
  return error == 0 ? "" : std::strerror(error);
}

}  // namespace

nav_msgs::OccupancyGrid ToMessage(const OccupancyGrid& grid,
                                  const Eigen::Isometry3d& T_frame_world) {
  nav_msgs::OccupancyGrid message;
  message.info.resolution = static_cast<float>(grid.cell_size_m);
  message.info.width = static_cast<uint32_t>(grid.width);
  message.info.height = static_cast<uint32_t>(grid.height);
  Eigen::Isometry3d T_grid_origin = Eigen::Isometry3d::Identity();
  T_grid_origin.translation() << grid.origin_m.x(), grid.origin_m.y(), 0.0;
  const Eigen::Isometry3d T_frame_origin = T_frame_world * grid.T_world_grid * T_grid_origin;
  const Eigen::Quaterniond q(T_frame_origin.rotation());
  message.info.origin.position.x = T_frame_origin.translation().x();
  message.info.origin.position.y = T_frame_origin.translation().y();
  message.info.origin.position.z = T_frame_origin.translation().z();
  message.info.origin.orientation.x = q.x();
  message.info.origin.orientation.y = q.y();
  message.info.origin.orientation.z = q.z();
  message.info.origin.orientation.w = q.w();
  message.data.assign(grid.cells.begin(), grid.cells.end());
  return message;
}

GridPublisher::GridPublisher(ros::NodeHandle& nh, const NodeConfig& node_config,
                             const Config& config, std::shared_ptr<const StaticMapper> mapper)
    : frame_id_(WorldDataFrameId(node_config)), config_(config), mapper_(std::move(mapper)) {
  grid_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("grid", 1, /*latch=*/true);
  save_srv_ = nh.advertiseService("save_grid", &GridPublisher::OnSave, this);
  timer_ = nh.createWallTimer(ros::WallDuration(std::min(1.0 / config_.grid.rate_hz, kPollS)),
                              [this](const ros::WallTimerEvent&) { OnTimer(); });
}

GridPublisher::~GridPublisher() {
  timer_.stop();
  save_srv_.shutdown();
}

void GridPublisher::SetWorldFrame(const Eigen::Isometry3d& T_frame_world) {
  gate_.SetWorldFrame(T_frame_world);
}

OccupancyGrid GridPublisher::Build(const StaticMapRays& rays,
                                   const Eigen::Isometry3d& T_frame_world) const {
  // The published frame's z axis (the base frame's up) in the tracker's world.
  const Eigen::Vector3d up_world = T_frame_world.rotation().transpose() * Eigen::Vector3d::UnitZ();
  return GridOf(rays, up_world, config_);
}

void GridPublisher::OnTimer() {
  PublishBuilt();
  if (grid_pub_.getNumSubscribers() == 0 || builder_.Pending() > 0) return;
  const ros::WallTime start = ros::WallTime::now();
  if (start < next_rebuild_) return;
  const std::optional<Eigen::Isometry3d> T_frame_world = gate_.TakeChange(mapper_->revision());
  if (!T_frame_world) return;
  auto rays = std::make_shared<const StaticMapRays>(mapper_->Rays());
  const double copy_ms = (ros::WallTime::now() - start).toSec() * 1e3;
  next_rebuild_ = start + ros::WallDuration(1.0 / config_.grid.rate_hz);
  const Eigen::Isometry3d T = *T_frame_world;
  builder_.Post([this, rays, T, copy_ms] {
    if (!builder_idle_priority_) {
      builder_idle_priority_ = true;
      idle_priority_problem_ = RunThisThreadWhenIdle();
    }
    Built built{std::nullopt, T, copy_ms, 0.0, ""};
    const ros::WallTime begin = ros::WallTime::now();
    try {
      built.grid = Build(*rays, T);
    } catch (const std::exception& e) {
      built.error = e.what();
    }
    built.build_ms = (ros::WallTime::now() - begin).toSec() * 1e3;
    const std::lock_guard<std::mutex> lock(built_mutex_);
    built_ = std::move(built);
  });
}

void GridPublisher::PublishBuilt() {
  std::optional<Built> built;
  {
    const std::lock_guard<std::mutex> lock(built_mutex_);
    built.swap(built_);
  }
  if (!built) return;
  if (!idle_priority_logged_ && builder_idle_priority_) {  // set before built_ (its mutex)
    idle_priority_logged_ = true;
    if (!idle_priority_problem_.empty()) {
      ROS_WARN("dslam: the grid's builder runs at normal priority (SCHED_IDLE refused: %s)",
               idle_priority_problem_.c_str());
    }
  }
  const double busy_ms = built->copy_ms + built->build_ms;
  next_rebuild_ = std::max(next_rebuild_, ros::WallTime::now() +
                                              ros::WallDuration(busy_ms * 1e-3 * kIdlePerBuild));
  if (!built->grid) {
    ROS_ERROR_THROTTLE(10.0, "dslam: grid not published: %s", built->error.c_str());
    return;
  }
  const OccupancyGrid& grid = *built->grid;
  CountRebuild(built->copy_ms, built->build_ms, grid);
  nav_msgs::OccupancyGrid message = ToMessage(grid, built->T_frame_world);
  message.header.stamp = ros::Time::now();
  message.header.frame_id = frame_id_;
  message.info.map_load_time = message.header.stamp;
  grid_pub_.publish(message);
  ROS_INFO_ONCE("dslam: grid %d x %d cells of %.3f m, floor %s", grid.width, grid.height,
                grid.cell_size_m, FloorSource(grid.floor));
}

void GridPublisher::CountRebuild(double copy_ms, double ms, const OccupancyGrid& grid) {
  const ros::WallTime now = ros::WallTime::now();
  if (rebuilds_.since.isZero()) rebuilds_.since = now;
  ++rebuilds_.count;
  rebuilds_.copy_total_ms += copy_ms;
  rebuilds_.total_ms += ms;
  rebuilds_.longest_ms = std::max(rebuilds_.longest_ms, ms);
  if ((now - rebuilds_.since).toSec() < 60.0) return;
  ROS_INFO("dslam: grid rebuilt %d times in the last minute: copying the map mean %.1f ms, "
           "building mean %.1f ms, longest %.1f ms (%d x %d cells, %d occupied)",
           rebuilds_.count, rebuilds_.copy_total_ms / rebuilds_.count,
           rebuilds_.total_ms / rebuilds_.count, rebuilds_.longest_ms, grid.width, grid.height,
           grid.Count(kCellOccupied));
  rebuilds_ = RebuildTimes();
  rebuilds_.since = now;
}

bool GridPublisher::OnSave(dslam::SaveGrid::Request& req, dslam::SaveGrid::Response& res) {
  return AnswerWrite(res, [&] {
    const OccupancyGrid grid =
        Build(mapper_->Rays(), gate_.WorldFrame().value_or(Eigen::Isometry3d::Identity()));
    WriteMapServerFiles(grid, req.path);
    res.occupied_cells = grid.Count(kCellOccupied);
    res.free_cells = grid.Count(kCellFree);
    return "wrote " + std::to_string(grid.width) + " x " + std::to_string(grid.height) +
           " cells (" + std::to_string(res.occupied_cells) + " occupied, " +
           std::to_string(res.free_cells) + " free) to " + req.path;
  });
}

}  // namespace ros_layer
}  // namespace dslam
