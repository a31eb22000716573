#pragma once
// Builders of the visualisation outputs: labelled point clouds, graph-edge markers and the
// feature image. Colours follow the paper's figures: static green, dynamic pink; kept edges
// green, culled edges red.

#include <vector>

#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/tracking/frame_result.h"

namespace dslam {
namespace ros_layer {

/// XYZRGB cloud of the matched points with the given label (`is_static`), positions mapped from
/// the odometry world into `header.frame_id` by T_frame_world [m]; static green, dynamic pink.
sensor_msgs::PointCloud2 MakeLabelledCloud(const std::vector<ObservedPoint>& points, bool is_static,
                                           const Eigen::Isometry3d& T_frame_world,
                                           const std_msgs::Header& header);

/// Two LINE_LIST markers (namespaces "kept", green, and "culled", red) of the front-end graph's
/// edges mapped by T_frame_world; an empty list is sent as a DELETE so old lines disappear.
visualization_msgs::MarkerArray MakeEdgeMarkers(const std::vector<GraphEdgeView>& edges,
                                                const Eigen::Isometry3d& T_frame_world,
                                                const std_msgs::Header& header);

/// A BGR copy of `colour` (BGR or grey) with each matched keypoint drawn as a circle coloured by
/// its label (static green, dynamic pink).
cv::Mat DrawFeatures(const cv::Mat& colour, const std::vector<ObservedPoint>& points);

}  // namespace ros_layer
}  // namespace dslam
