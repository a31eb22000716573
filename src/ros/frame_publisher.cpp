#include "dslam/ros/frame_publisher.h"

#include <vector>

#include <cv_bridge/cv_bridge.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_eigen/tf2_eigen.h>
#include <visualization_msgs/MarkerArray.h>

#include "dslam/ros/conversions.h"
#include "dslam/ros/visualisation.h"

namespace dslam {
namespace ros_layer {
namespace {

/// A 6x6 matrix into a message's row-major covariance array (nav_msgs/Odometry's pose and twist).
void CopyCovariance(const Eigen::Matrix<double, 6, 6>& covariance, boost::array<double, 36>* out) {
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) (*out)[6 * r + c] = covariance(r, c);
  }
}

}  // namespace

void FillBackEndStatus(const BackEndStatus& b, dslam::FrameStatus* s) {
  s->backend_ran = b.ba.ran;
  s->ba_rejected = b.ba.rejected;
  s->window_keyframes = b.window_keyframes;
  s->ba_points = b.ba.points;
  s->ba_outliers = b.ba.outliers;
  s->ba_iterations = b.ba.iterations;
  s->ba_ms = b.ba.time_ms;
  s->spd_ran = b.spd.ran;
  s->spd_points = b.spd.graph.points;
  s->spd_culled_edges = b.spd.graph.culled_edges;
  s->spd_unmarked = b.spd.unmarked;
  s->spd_ms = b.spd.total_ms;
}

void FillLoopStatus(const LoopStatus& loops, dslam::FrameStatus* s) {
  s->loop_closures = loops.loop_closures;
  s->loop_keyframes = loops.loop_keyframes;
  s->loop_ms = loops.loop_ms;
}

FramePublisher::FramePublisher(ros::NodeHandle& nh, const NodeConfig& config) : config_(config) {
  odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
  path_pub_ = nh.advertise<nav_msgs::Path>("path", 1);
  status_pub_ = nh.advertise<dslam::FrameStatus>("status", 10);
  static_pub_ = nh.advertise<sensor_msgs::PointCloud2>("static_points", 1);
  dynamic_pub_ = nh.advertise<sensor_msgs::PointCloud2>("dynamic_points", 1);
  edges_pub_ = nh.advertise<visualization_msgs::MarkerArray>("graph_edges", 1);
  features_pub_ = nh.advertise<sensor_msgs::Image>("features", 1);
}

void FramePublisher::Publish(const FrameResult& result, const RgbdFrame& frame,
                             const std_msgs::Header& header, const Eigen::Isometry3d& T_base_camera,
                             const FrameCounters& counters, double latency_ms) {
  odom_.Add(result);
  twist_.Add(result, odom_.T_odom_camera(), T_base_camera);
  std_msgs::Header odom_header = header;
  odom_header.frame_id = config_.odom_frame;
  const WorldDataFrame world = WorldData(T_base_camera);
  std_msgs::Header world_header = header;
  world_header.frame_id = world.frame_id;
  if (result.has_pose) {
    PublishOdom(result, odom_header, T_base_camera);
    // The base's pose in the world data's frame: T_frame_world * T_world_camera * T_camera_base.
    geometry_msgs::PoseStamped stamped;
    stamped.header = world_header;
    stamped.pose =
        tf2::toMsg(world.T_frame_world * result.T_world_camera * T_base_camera.inverse());
    UpdatePath(stamped);
  }
  PublishVisuals(result, frame, header, world_header, world.T_frame_world);
  PublishStatus(result, ToString(result.state), odom_header, counters, latency_ms);
}

WorldDataFrame FramePublisher::WorldData(const Eigen::Isometry3d& T_base_camera) const {
  WorldDataFrame world;
  world.frame_id = WorldDataFrameId(config_);
  // The map frame is the base frame at the tracker's first frame (its world's origin).
  world.T_frame_world =
      config_.publish_map_tf ? T_base_camera : T_base_camera * odom_.T_map_odom().inverse();
  return world;
}

void FramePublisher::PublishOdom(const FrameResult& result, const std_msgs::Header& odom_header,
                                 const Eigen::Isometry3d& T_base_camera) {
  const Eigen::Isometry3d T_odom_base = OdomFromBase(odom_.T_odom_camera(), T_base_camera);
  std::vector<geometry_msgs::TransformStamped> transforms;
  if (config_.publish_map_tf) {
    transforms.push_back(tf2::eigenToTransform(MapFromOdom(odom_.T_map_odom(), T_base_camera)));
    transforms.back().header = odom_header;
    transforms.back().header.frame_id = config_.map_frame;
    transforms.back().child_frame_id = config_.odom_frame;
  }
  if (config_.publish_tf) {
    transforms.push_back(tf2::eigenToTransform(T_odom_base));
    transforms.back().header = odom_header;
    transforms.back().child_frame_id = config_.base_frame;
  }
  if (!transforms.empty()) tf_broadcaster_.sendTransform(transforms);
  nav_msgs::Odometry odom;
  odom.header = odom_header;
  odom.child_frame_id = config_.base_frame;
  odom.pose.pose = tf2::toMsg(T_odom_base);
  // The information is of the camera's pose in its own frame; the odom frame's rotation maps it.
  CopyCovariance(OdomCovariance(result.information, odom_.T_odom_camera(), T_base_camera),
                 &odom.pose.covariance);
  odom.twist.twist = tf2::toMsg(twist_.velocity());
  CopyCovariance(twist_.covariance(), &odom.twist.covariance);
  odom_pub_.publish(odom);
}

void FramePublisher::UpdatePath(const geometry_msgs::PoseStamped& pose) {
  path_.push_back(pose);
  while (path_.size() > static_cast<size_t>(config_.path_max_poses)) path_.pop_front();
  const ros::WallTime now = ros::WallTime::now();
  if (path_pub_.getNumSubscribers() == 0 ||
      (now - path_published_).toSec() < 1.0 / config_.path_rate_hz) {
    return;
  }
  path_published_ = now;
  nav_msgs::Path path;
  path.header = pose.header;
  path.poses.assign(path_.begin(), path_.end());
  path_pub_.publish(path);
}

bool FramePublisher::WantsPoints() const {
  return static_pub_.getNumSubscribers() > 0 || dynamic_pub_.getNumSubscribers() > 0 ||
         features_pub_.getNumSubscribers() > 0;
}

bool FramePublisher::WantsEdges() const { return edges_pub_.getNumSubscribers() > 0; }

void FramePublisher::PublishRejected(const std::string& problem, const std_msgs::Header& header,
                                     const FrameCounters& counters, double latency_ms) {
  FrameResult rejected;
  rejected.stamp_s = header.stamp.toSec();
  rejected.message = problem;
  std_msgs::Header odom_header = header;
  odom_header.frame_id = config_.odom_frame;
  PublishStatus(rejected, "rejected", odom_header, counters, latency_ms);
}

void FramePublisher::PublishStatus(const FrameResult& r, const std::string& state,
                                   const std_msgs::Header& odom_header,
                                   const FrameCounters& counters, double latency_ms) {
  dslam::FrameStatus s;
  s.header = odom_header;
  s.state = state;
  s.has_pose = r.has_pose;
  s.keyframe = r.keyframe;
  s.reset = r.reset;
  s.message = r.message;
  const FrameCounts& c = r.counts;
  s.features = c.features;
  s.features_with_depth = c.features_with_depth;
  s.tracked = c.tracked;
  s.static_points = c.static_points;
  s.dynamic_points = c.dynamic_points;
  s.pose_inliers = c.pose_inliers;
  s.pose_observations = c.pose_observations;
  s.pose_chi2_per_dof = c.pose_chi2_per_dof;
  s.graph_points = c.graph_points;
  s.graph_edges = c.graph_edges;
  s.culled_edges = c.culled_edges;
  s.map_points = c.map_points;
  s.new_points = c.new_points;
  const StageTimes& t = r.times;
  s.features_ms = t.features_ms;
  s.matching_ms = t.matching_ms;
  s.initial_pose_ms = t.initial_pose_ms;
  s.static_points_ms = t.static_points_ms;
  s.refine_ms = t.refine_ms;
  s.mapping_ms = t.mapping_ms;
  s.total_ms = t.total_ms;
  s.tracking_ms = t.tracking_ms;
  FillBackEndStatus(r.backend, &s);
  s.backend_delivered = r.backend_thread.delivered;
  s.backend_backlog = r.backend_thread.backlog;
  FillLoopStatus(loops_, &s);
  s.latency_ms = latency_ms;
  s.frames_received = counters.received;
  s.frames_processed = counters.processed;
  s.frames_dropped = counters.dropped;
  s.frames_rejected = counters.rejected;
  s.errors = counters.errors;
  s.map_lock_max_ms = counters.map_lock_max_ms;
  status_pub_.publish(s);
}

void FramePublisher::PublishVisuals(const FrameResult& result, const RgbdFrame& frame,
                                    const std_msgs::Header& header,
                                    const std_msgs::Header& world_header,
                                    const Eigen::Isometry3d& T_frame_world) {
  if (static_pub_.getNumSubscribers() > 0) {
    static_pub_.publish(MakeLabelledCloud(result.points, true, T_frame_world, world_header));
  }
  if (dynamic_pub_.getNumSubscribers() > 0) {
    dynamic_pub_.publish(MakeLabelledCloud(result.points, false, T_frame_world, world_header));
  }
  if (edges_pub_.getNumSubscribers() > 0) {
    edges_pub_.publish(MakeEdgeMarkers(result.edges, T_frame_world, world_header));
  }
  if (features_pub_.getNumSubscribers() > 0) {
    const cv_bridge::CvImage image(header, "bgr8", DrawFeatures(frame.colour, result.points));
    features_pub_.publish(image.toImageMsg());
  }
}

}  // namespace ros_layer
}  // namespace dslam
