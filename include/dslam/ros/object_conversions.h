#pragma once
// Moving objects (part mapping) as ROS messages: dslam/MovingObjects and an rviz MarkerArray
// (boxes, velocity arrows, id labels), in the frame of the tracker's world data (map, or odom).

#include <vector>

#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>
#include <Eigen/Geometry>

#include "dslam/MovingObjects.h"
#include "dslam/mapping/object_tracker.h"

namespace dslam {
namespace ros_layer {

/// The objects re-expressed in `header.frame_id` by T_frame_world [m] (WorldDataFrame: the camera
/// mount T_base_camera into the map frame, the base at the first frame, whose optical frame is
/// the tracker's world). Extents become those of the box aligned with the frame's axes around
/// the rotated world-axis box.
dslam::MovingObjects MakeMovingObjects(const std::vector<TrackedObject>& objects,
                                       const Eigen::Isometry3d& T_frame_world,
                                       const std_msgs::Header& header);

/// rviz markers of `message`: a DELETEALL, then per object a translucent box (namespace
/// "boxes"), a velocity arrow from its centre (1 s of motion; "velocity") and its id ("ids").
visualization_msgs::MarkerArray MakeObjectMarkers(const dslam::MovingObjects& message);

}  // namespace ros_layer
}  // namespace dslam
