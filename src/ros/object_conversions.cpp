#include "dslam/ros/object_conversions.h"

#include <string>

namespace dslam {
namespace ros_layer {
namespace {

geometry_msgs::Vector3 ToVector3(const Eigen::Vector3d& v) {
  geometry_msgs::Vector3 out;
  out.x = v.x();
  out.y = v.y();
  out.z = v.z();
  return out;
}

visualization_msgs::Marker BaseMarker(const std_msgs::Header& header, const char* ns, int id,
                                      int type) {
  visualization_msgs::Marker marker;
  marker.header = header;
  marker.ns = ns;
  marker.id = id;
  marker.type = type;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.lifetime = ros::Duration(0.5);  // gone when the object is no longer reported
  return marker;
}

/// A colour per id (the same id keeps its colour).
std_msgs::ColorRGBA IdColour(uint32_t id, float alpha) {
  std_msgs::ColorRGBA c;
  const uint32_t h = id * 2654435761u;
  c.r = 0.3f + 0.7f * ((h >> 8) & 0xff) / 255.0f;
  c.g = 0.3f + 0.7f * ((h >> 16) & 0xff) / 255.0f;
  c.b = 0.3f + 0.7f * ((h >> 24) & 0xff) / 255.0f;
  c.a = alpha;
  return c;
}

}  // namespace

dslam::MovingObjects MakeMovingObjects(const std::vector<TrackedObject>& objects,
                                       const Eigen::Isometry3d& T_frame_world,
                                       const std_msgs::Header& header) {
  dslam::MovingObjects message;
  message.header = header;
  const Eigen::Matrix3d R = T_frame_world.linear();
  for (const TrackedObject& o : objects) {
    dslam::MovingObject m;
    m.id = static_cast<uint32_t>(o.id);
    const Eigen::Vector3d p = T_frame_world * o.position_world;
    m.position.x = p.x();
    m.position.y = p.y();
    m.position.z = p.z();
    m.velocity = ToVector3(R * o.velocity_world);
    m.extent = ToVector3(R.cwiseAbs() * o.extent);
    m.point_count = static_cast<uint32_t>(o.points);
    m.age_s = o.age_s;
    message.objects.push_back(m);
  }
  return message;
}

visualization_msgs::MarkerArray MakeObjectMarkers(const dslam::MovingObjects& message) {
  visualization_msgs::MarkerArray markers;
  visualization_msgs::Marker clear;
  clear.header = message.header;
  clear.action = visualization_msgs::Marker::DELETEALL;
  markers.markers.push_back(clear);
  for (const dslam::MovingObject& o : message.objects) {
    const int id = static_cast<int>(o.id);
    auto box = BaseMarker(message.header, "boxes", id, visualization_msgs::Marker::CUBE);
    box.pose.position = o.position;
    box.scale = o.extent;
    box.color = IdColour(o.id, 0.35f);
    markers.markers.push_back(box);
    auto arrow = BaseMarker(message.header, "velocity", id, visualization_msgs::Marker::ARROW);
    geometry_msgs::Point tip = o.position;
    tip.x += o.velocity.x;
    tip.y += o.velocity.y;
    tip.z += o.velocity.z;
    arrow.points = {o.position, tip};
    arrow.scale.x = 0.04;  // shaft diameter [m]
    arrow.scale.y = 0.08;  // head diameter [m]
    arrow.scale.z = 0.1;   // head length [m]
    arrow.color = IdColour(o.id, 1.0f);
    markers.markers.push_back(arrow);
    auto label =
        BaseMarker(message.header, "ids", id, visualization_msgs::Marker::TEXT_VIEW_FACING);
    label.pose.position = o.position;
    label.pose.position.z += 0.5 * o.extent.z + 0.15;
    label.scale.z = 0.2;  // text height [m]
    label.color = IdColour(o.id, 1.0f);
    label.text = "#" + std::to_string(o.id);
    markers.markers.push_back(label);
  }
  return markers;
}

}  // namespace ros_layer
}  // namespace dslam
