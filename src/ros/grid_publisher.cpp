#include "dslam/ros/grid_publisher.h"

#include <algorithm>
#include <string>

#include "dslam/ros/service_reply.h"

namespace dslam {
namespace ros_layer {

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
  timer_ = nh.createWallTimer(ros::WallDuration(1.0 / config_.grid.rate_hz),
                              [this](const ros::WallTimerEvent&) { OnTimer(); });
}

GridPublisher::~GridPublisher() {
  timer_.stop();
  save_srv_.shutdown();
}

void GridPublisher::SetWorldFrame(const Eigen::Isometry3d& T_frame_world) {
  gate_.SetWorldFrame(T_frame_world);
}

OccupancyGrid GridPublisher::Build(const Eigen::Isometry3d& T_frame_world) const {
  // The published frame's z axis (the base frame's up) in the tracker's world.
  const Eigen::Vector3d up_world = T_frame_world.rotation().transpose() * Eigen::Vector3d::UnitZ();
  return GridOf(mapper_->Rays(), up_world, config_);
}

void GridPublisher::OnTimer() {
  if (grid_pub_.getNumSubscribers() == 0) return;
  if (ros::WallTime::now() < next_rebuild_) return;
  const std::optional<Eigen::Isometry3d> T_frame_world = gate_.TakeChange(mapper_->revision());
  if (!T_frame_world) return;
  try {
    const ros::WallTime start = ros::WallTime::now();
    const OccupancyGrid grid = Build(*T_frame_world);  // outside the gate's lock
    const ros::WallTime end = ros::WallTime::now();
    CountRebuild((end - start).toSec() * 1e3, grid);
    next_rebuild_ = end + ros::WallDuration((end - start).toSec() * kIdlePerBuild);
    nav_msgs::OccupancyGrid message = ToMessage(grid, *T_frame_world);
    message.header.stamp = ros::Time::now();
    message.header.frame_id = frame_id_;
    message.info.map_load_time = message.header.stamp;
    grid_pub_.publish(message);
    ROS_INFO_ONCE("dslam: grid %d x %d cells of %.3f m, floor %s", grid.width, grid.height,
                  grid.cell_size_m, FloorSource(grid.floor));
  } catch (const std::exception& e) {
    ROS_ERROR_THROTTLE(10.0, "dslam: grid not published: %s", e.what());
  }
}

void GridPublisher::CountRebuild(double ms, const OccupancyGrid& grid) {
  const ros::WallTime now = ros::WallTime::now();
  if (rebuilds_.since.isZero()) rebuilds_.since = now;
  ++rebuilds_.count;
  rebuilds_.total_ms += ms;
  rebuilds_.longest_ms = std::max(rebuilds_.longest_ms, ms);
  if ((now - rebuilds_.since).toSec() < 60.0) return;
  ROS_INFO("dslam: grid rebuilt %d times in the last minute, mean %.1f ms, longest %.1f ms "
           "(%d x %d cells, %d occupied)",
           rebuilds_.count, rebuilds_.total_ms / rebuilds_.count, rebuilds_.longest_ms, grid.width,
           grid.height, grid.Count(kCellOccupied));
  rebuilds_ = RebuildTimes();
  rebuilds_.since = now;
}

bool GridPublisher::OnSave(dslam::SaveGrid::Request& req, dslam::SaveGrid::Response& res) {
  return AnswerWrite(res, [&] {
    const OccupancyGrid grid = Build(gate_.WorldFrame().value_or(Eigen::Isometry3d::Identity()));
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
