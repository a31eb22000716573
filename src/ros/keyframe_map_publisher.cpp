#include "dslam/ros/keyframe_map_publisher.h"

#include <utility>

#include <nav_msgs/Path.h>
#include <visualization_msgs/MarkerArray.h>

namespace dslam {
namespace ros_layer {

KeyFrameMapPublisher::KeyFrameMapPublisher(ros::NodeHandle& nh, const Slam& slam,
                                           std::shared_ptr<const LoopClosing> loop_closing)
    : slam_(slam), loop_closing_(std::move(loop_closing)) {
  path_pub_ = nh.advertise<nav_msgs::Path>("keyframe_path", 1, /*latch=*/true);
  loops_pub_ = nh.advertise<visualization_msgs::MarkerArray>("loop_edges", 1, /*latch=*/true);
}

bool KeyFrameMapPublisher::RefreshLoopStatus(bool keyframe) {
  const ros::WallTime now = ros::WallTime::now();
  if (!loop_closing_ || (!keyframe && (now - refreshed_).toSec() < kLoopStatusPeriodS)) {
    return false;
  }
  refreshed_ = now;
  const int before = loop_status_.loop_closures;
  loop_status_ = SummariseLoops(loop_closing_->work());
  if (loop_status_.loop_closures == before) return false;
  loops_ = LoopKeyFramesOf(loop_closing_->loops());  // copied only when a loop was closed
  return true;
}

bool KeyFrameMapPublisher::Due(const ros::Publisher& publisher, bool changed,
                               uint32_t* subscribers) {
  const uint32_t now = publisher.getNumSubscribers();
  const bool arrived = now > *subscribers;
  *subscribers = now;
  return now > 0 && (changed || arrived);
}

void KeyFrameMapPublisher::Publish(bool changed, const std_msgs::Header& header,
                                   const Eigen::Isometry3d& T_frame_world,
                                   const Eigen::Isometry3d& T_base_camera) {
  const bool path_due = Due(path_pub_, changed, &path_subscribers_);
  const bool loops_due = Due(loops_pub_, changed, &loops_subscribers_);
  if (!path_due && !loops_due) return;
  std::vector<KeyFrameView> keyframes;
  slam_.ReadMap([&keyframes](const Map& map) { keyframes = KeyFrameViews(map); });
  if (path_due) {
    path_pub_.publish(MakeKeyFramePath(keyframes, T_frame_world, T_base_camera, header));
  }
  if (loops_due) {
    loops_pub_.publish(MakeLoopEdgeMarkers(loops_, keyframes, T_frame_world, header));
  }
}

}  // namespace ros_layer
}  // namespace dslam
