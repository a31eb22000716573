#pragma once
// REP 105 for the tracker's poses: the odom pose moves only by the motion tracked from one frame
// to the next, so it stays continuous; the map -> odom transform takes every jump of the
// tracker's pose (the back end correcting the previous pose between frames, relocalisation, the
// first pose after lost frames). No ROS headers: test_ros tests it without a node.

#include <Eigen/Geometry>

#include "dslam/tracking/frame_result.h"

namespace dslam {
namespace ros_layer {

/// Splits the tracker's camera poses T_world_camera (the tracker's world is the map frame) into
/// a continuous T_odom_camera and T_map_odom, with T_map_odom * T_odom_camera = T_world_camera
/// after every frame with a pose. Frames are the camera's optical conventions: odom is the
/// optical frame of the camera where odom started (the ROS layer conjugates both with the camera
/// mount). T_map_odom is exactly the identity until the first correction or jump, and changes
/// only at one. Call from one thread.
class OdomIntegrator {
 public:
  /// Takes one frame's result; a frame without a pose changes nothing. The first pose (after
  /// construction or Restart) starts odom at it with T_map_odom the identity. Then, with
  /// has_previous_pose: T_odom_camera moves by the tracked motion T_world_previous_camera^-1 *
  /// T_world_camera; T_map_odom changes only when T_world_previous_camera differs from the last
  /// pose taken here (the back end corrected it between the frames). Without it (after lost
  /// frames, on a relocalised frame): T_odom_camera stays, T_map_odom takes the jump.
  void Add(const FrameResult& result);

  /// Forgets everything: the next pose starts odom again with T_map_odom the identity (the
  /// tracker started a new world at the origin: time went backwards).
  void Restart() { *this = OdomIntegrator(); }

  /// Whether a pose was taken since construction or Restart.
  bool has_pose() const { return has_pose_; }
  /// [optical frame -> odom] The camera pose in odom after the last pose taken [m].
  const Eigen::Isometry3d& T_odom_camera() const { return T_odom_camera_; }
  /// [odom -> map (the tracker's world)] [m]; the identity before the first correction or jump.
  const Eigen::Isometry3d& T_map_odom() const { return T_map_odom_; }

 private:
  bool has_pose_ = false;
  Eigen::Isometry3d T_odom_camera_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_map_odom_ = Eigen::Isometry3d::Identity();
  /// [optical frame -> map] The last pose taken, as the tracker reported it.
  Eigen::Isometry3d T_map_last_camera_ = Eigen::Isometry3d::Identity();
};

}  // namespace ros_layer
}  // namespace dslam
