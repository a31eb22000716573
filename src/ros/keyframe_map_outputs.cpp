#include "dslam/ros/keyframe_map_outputs.h"

#include <unordered_map>

#include <tf2_eigen/tf2_eigen.h>

namespace dslam {
namespace ros_layer {

std::vector<KeyFrameView> KeyFrameViews(const Map& map) {
  std::vector<KeyFrameView> views;
  const std::vector<const KeyFrame*> keyframes = map.AllKeyFrames();
  views.reserve(keyframes.size());
  for (const KeyFrame* keyframe : keyframes) {
    views.push_back({keyframe->id, keyframe->stamp_s, keyframe->T_world_camera});
  }
  return views;
}

nav_msgs::Path MakeKeyFramePath(const std::vector<KeyFrameView>& keyframes,
                                const Eigen::Isometry3d& T_frame_world,
                                const Eigen::Isometry3d& T_base_camera,
                                const std_msgs::Header& header) {
  nav_msgs::Path path;
  path.header = header;
  path.poses.reserve(keyframes.size());
  const Eigen::Isometry3d T_camera_base = T_base_camera.inverse();
  for (const KeyFrameView& keyframe : keyframes) {
    geometry_msgs::PoseStamped pose;
    pose.header.stamp.fromSec(keyframe.stamp_s);
    pose.header.frame_id = header.frame_id;
    pose.pose = tf2::toMsg(T_frame_world * keyframe.T_world_camera * T_camera_base);
    path.poses.push_back(pose);
  }
  return path;
}

std::vector<LoopKeyFrames> LoopKeyFramesOf(const std::vector<ClosedLoop>& loops) {
  std::vector<LoopKeyFrames> ids;
  ids.reserve(loops.size());
  for (const ClosedLoop& loop : loops) {
    ids.push_back({loop.detection.query_keyframe_id, loop.detection.match_keyframe_id});
  }
  return ids;
}

visualization_msgs::MarkerArray MakeLoopEdgeMarkers(const std::vector<LoopKeyFrames>& loops,
                                                    const std::vector<KeyFrameView>& keyframes,
                                                    const Eigen::Isometry3d& T_frame_world,
                                                    const std_msgs::Header& header) {
  std::unordered_map<int, Eigen::Vector3d> centres;  // camera centres in the header's frame
  for (const KeyFrameView& keyframe : keyframes) {
    centres[keyframe.id] = T_frame_world * keyframe.T_world_camera.translation();
  }
  visualization_msgs::Marker lines;
  lines.header = header;
  lines.ns = "loops";
  lines.id = 0;
  lines.type = visualization_msgs::Marker::LINE_LIST;
  lines.action = visualization_msgs::Marker::ADD;
  lines.pose.orientation.w = 1.0;
  lines.scale.x = 0.02;  // [m] line width
  lines.color.r = 1.0f;
  lines.color.g = 0.5f;
  lines.color.a = 1.0f;
  for (const LoopKeyFrames& loop : loops) {
    const auto query = centres.find(loop.query_id);
    const auto match = centres.find(loop.match_id);
    if (query == centres.end() || match == centres.end()) continue;
    lines.points.push_back(tf2::toMsg(query->second));
    lines.points.push_back(tf2::toMsg(match->second));
  }
  if (lines.points.empty()) lines.action = visualization_msgs::Marker::DELETE;
  visualization_msgs::MarkerArray out;
  out.markers.push_back(lines);
  return out;
}

LoopStatus SummariseLoops(const LoopWork& work) {
  LoopStatus status;
  status.loop_closures = work.loops;
  status.loop_keyframes = work.keyframes;
  status.loop_ms = work.last_ms;
  return status;
}

Trajectory CurrentSegment(const Trajectory& poses, double first_stamp_s) {
  if (poses.empty()) return {};
  size_t begin = poses.size() - 1;  // the last run of non-decreasing stamps begins here
  while (begin > 0 && poses[begin - 1].stamp_s <= poses[begin].stamp_s) --begin;
  while (begin < poses.size() && poses[begin].stamp_s < first_stamp_s) ++begin;
  return Trajectory(poses.begin() + static_cast<std::ptrdiff_t>(begin), poses.end());
}

}  // namespace ros_layer
}  // namespace dslam
