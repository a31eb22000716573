#include "dslam/ros/visualisation.h"

#include <sensor_msgs/point_cloud2_iterator.h>
#include <opencv2/imgproc.hpp>

namespace dslam {
namespace ros_layer {
namespace {

// Paper colours (RGB): static green, dynamic pink.
const cv::Vec3b kStaticRgb(40, 200, 60);
const cv::Vec3b kDynamicRgb(255, 80, 200);

geometry_msgs::Point ToPoint(const Eigen::Vector3d& p) {
  geometry_msgs::Point out;
  out.x = p.x();
  out.y = p.y();
  out.z = p.z();
  return out;
}

visualization_msgs::Marker LineList(const std_msgs::Header& header, const char* ns, int id, float r,
                                    float g, float b) {
  visualization_msgs::Marker m;
  m.header = header;
  m.ns = ns;
  m.id = id;
  m.type = visualization_msgs::Marker::LINE_LIST;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = 0.005;  // [m] line width
  m.color.r = r;
  m.color.g = g;
  m.color.b = b;
  m.color.a = 0.8f;
  return m;
}

}  // namespace

sensor_msgs::PointCloud2 MakeLabelledCloud(const std::vector<ObservedPoint>& points, bool is_static,
                                           const Eigen::Isometry3d& T_frame_world,
                                           const std_msgs::Header& header) {
  size_t n = 0;
  for (const auto& p : points) n += p.is_static == is_static;
  sensor_msgs::PointCloud2 cloud;
  cloud.header = header;
  sensor_msgs::PointCloud2Modifier modifier(cloud);
  modifier.setPointCloud2FieldsByString(2, "xyz", "rgb");
  modifier.resize(n);
  sensor_msgs::PointCloud2Iterator<float> x(cloud, "x"), y(cloud, "y"), z(cloud, "z");
  sensor_msgs::PointCloud2Iterator<uint8_t> rgb(cloud, "rgb");  // bytes b, g, r, a
  const cv::Vec3b colour = is_static ? kStaticRgb : kDynamicRgb;
  for (const auto& p : points) {
    if (p.is_static != is_static) continue;
    const Eigen::Vector3d q = T_frame_world * p.p_world;
    *x = static_cast<float>(q.x());
    *y = static_cast<float>(q.y());
    *z = static_cast<float>(q.z());
    rgb[0] = colour[2];
    rgb[1] = colour[1];
    rgb[2] = colour[0];
    ++x, ++y, ++z, ++rgb;
  }
  return cloud;
}

visualization_msgs::MarkerArray MakeEdgeMarkers(const std::vector<GraphEdgeView>& edges,
                                                const Eigen::Isometry3d& T_frame_world,
                                                const std_msgs::Header& header) {
  visualization_msgs::Marker kept = LineList(header, "kept", 0, 0.1f, 0.8f, 0.2f);
  visualization_msgs::Marker culled = LineList(header, "culled", 1, 0.9f, 0.1f, 0.1f);
  for (const auto& e : edges) {
    auto& m = e.kept ? kept : culled;
    m.points.push_back(ToPoint(T_frame_world * e.a_world));
    m.points.push_back(ToPoint(T_frame_world * e.b_world));
  }
  visualization_msgs::MarkerArray out;
  for (auto* m : {&kept, &culled}) {
    if (m->points.empty()) m->action = visualization_msgs::Marker::DELETE;
    out.markers.push_back(*m);
  }
  return out;
}

cv::Mat DrawFeatures(const cv::Mat& colour, const std::vector<ObservedPoint>& points) {
  cv::Mat out;
  if (colour.channels() == 1)
    cv::cvtColor(colour, out, cv::COLOR_GRAY2BGR);
  else
    out = colour.clone();
  for (const auto& p : points) {
    const cv::Vec3b c = p.is_static ? kStaticRgb : kDynamicRgb;
    cv::circle(out, cv::Point2d(p.uv_raw.x(), p.uv_raw.y()), 4, cv::Scalar(c[2], c[1], c[0]), 1,
               cv::LINE_AA);
  }
  return out;
}

}  // namespace ros_layer
}  // namespace dslam
