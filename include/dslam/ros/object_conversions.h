#pragma once
// Moving objects (part mapping) as ROS messages: dslam/MovingObjects and an rviz MarkerArray
// (boxes, velocity arrows, id labels), in the odometry frame.

#include <vector>

#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>
#include <Eigen/Geometry>

#include "dslam/MovingObjects.h"
#include "dslam/mapping/object_tracker.h"

namespace dslam {
namespace ros_layer {

/// The objects re-expressed in the odom frame (T_odom_world = T_base_camera: odom is the base at
/// the first frame, the odometry's world is the camera's optical frame then). Extents become
/// those of the odom-axis-aligned box around the rotated world-axis box.
dslam::MovingObjects MakeMovingObjects(const std::vector<TrackedObject>& objects,
                                       const Eigen::Isometry3d& T_base_camera,
                                       const std_msgs::Header& odom_header);

/// rviz markers of `message`: a DELETEALL, then per object a translucent box (namespace
/// "boxes"), a velocity arrow from its centre (1 s of motion; "velocity") and its id ("ids").
visualization_msgs::MarkerArray MakeObjectMarkers(const dslam::MovingObjects& message);

}  // namespace ros_layer
}  // namespace dslam
