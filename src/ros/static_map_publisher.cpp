#include "dslam/ros/static_map_publisher.h"

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl_conversions/pcl_conversions.h>
#include <sensor_msgs/PointCloud2.h>

#include "dslam/mapping/octomap_file.h"
#include "dslam/ros/service_reply.h"

namespace dslam {
namespace ros_layer {
namespace {

// `cloud` [m, world frame] in the frame T_frame_world maps it to, as a PointCloud2.
sensor_msgs::PointCloud2 ToMessage(const ColouredCloud& cloud,
                                   const Eigen::Isometry3d& T_frame_world) {
  const Eigen::Isometry3f T = T_frame_world.cast<float>();
  pcl::PointCloud<pcl::PointXYZRGB> points;
  points.reserve(cloud.size());
  for (const ColouredPoint& point : cloud) {
    pcl::PointXYZRGB q(point.r, point.g, point.b);
    q.getVector3fMap() = T * point.p;
    points.push_back(q);
  }
  sensor_msgs::PointCloud2 message;
  pcl::toROSMsg(points, message);
  return message;
}

}  // namespace

StaticMapPublisher::StaticMapPublisher(ros::NodeHandle& nh, const NodeConfig& config,
                                       std::shared_ptr<const StaticMapper> mapper,
                                       double voxel_size_m)
    : frame_id_(WorldDataFrameId(config)), mapper_(std::move(mapper)), voxel_size_m_(voxel_size_m) {
  map_pub_ = nh.advertise<sensor_msgs::PointCloud2>("static_map", 1, /*latch=*/true);
  save_srv_ = nh.advertiseService("save_map", &StaticMapPublisher::OnSave, this);
  save_octomap_srv_ = nh.advertiseService("save_octomap", &StaticMapPublisher::OnSaveOctoMap, this);
  timer_ = nh.createWallTimer(ros::WallDuration(1.0 / config.static_map_rate_hz),
                              [this](const ros::WallTimerEvent&) { OnTimer(); });
}

StaticMapPublisher::~StaticMapPublisher() {
  timer_.stop();
  save_srv_.shutdown();
  save_octomap_srv_.shutdown();
}

void StaticMapPublisher::SetWorldFrame(const Eigen::Isometry3d& T_frame_world) {
  gate_.SetWorldFrame(T_frame_world);
}

void StaticMapPublisher::OnTimer() {
  if (map_pub_.getNumSubscribers() == 0) return;
  const std::optional<Eigen::Isometry3d> T_frame_world = gate_.TakeChange(mapper_->revision());
  if (!T_frame_world) return;
  // The cloud is built outside the gate's lock (Cloud takes the mapper's).
  sensor_msgs::PointCloud2 message = ToMessage(mapper_->Cloud(), *T_frame_world);
  message.header.stamp = ros::Time::now();
  message.header.frame_id = frame_id_;
  map_pub_.publish(message);
}

bool StaticMapPublisher::OnSave(dslam::SaveMap::Request& req, dslam::SaveMap::Response& res) {
  return AnswerWrite(res, [&] {
    const ColouredCloud cloud = mapper_->Cloud();
    WritePcd(req.path, cloud);
    res.points = static_cast<int>(cloud.size());
    return "wrote " + std::to_string(res.points) + " points to " + req.path;
  });
}

bool StaticMapPublisher::OnSaveOctoMap(dslam::SaveMap::Request& req,
                                       dslam::SaveMap::Response& res) {
  return AnswerWrite(res, [&] {
    const OctoMapStats stats = WriteOctoMap(mapper_->Rays(), voxel_size_m_, req.path);
    res.points = static_cast<int>(stats.occupied_leaves);
    return "wrote " + std::to_string(stats.occupied_leaves) + " occupied and " +
           std::to_string(stats.free_leaves) + " free leaves to " + req.path;
  });
}

}  // namespace ros_layer
}  // namespace dslam
