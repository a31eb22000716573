#pragma once
// Parameters of the ROS layer (the odometry nodelet's own ~keys), described with the same
// FieldInfo visitor as the core Config sections so that one loader reads and checks both.

#include <string>

#include "dslam/core/config_field.h"

namespace dslam {
namespace ros_layer {

/// Top-level private parameters of dslam/OdometryNodelet (~odom_frame, ~queue_size, ...).
struct NodeConfig {
  std::string odom_frame = "odom";       ///< fixed frame of odometry, path, clouds (REP 105)
  std::string base_frame = "base_link";  ///< robot body frame, x forward z up (REP 103)
  /// Optical frame of the colour camera; empty: the colour image's header frame id.
  std::string camera_frame = "";
  bool publish_tf = true;   ///< broadcast odom -> base_frame (and the default mount)
  bool exact_sync = false;  ///< ExactTime instead of ApproximateTime synchronisation
  int queue_size = 10;      ///< [-] message_filters queue length per input
  /// camera.yaml with calibrated intrinsics; empty: use camera_info.
  std::string camera_yaml = "";
  int path_max_poses = 10000;  ///< [-] poses kept in the published path
  double tf_wait_s = 0.0;      ///< [s] wait for base_frame <- camera frame at the first frame

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    v(FieldInfo{"odom_frame", "-", 0, 0, "fixed odometry frame (REP 105)", {}}, s.odom_frame);
    v(FieldInfo{"base_frame", "-", 0, 0, "robot base frame, x forward, z up", {}}, s.base_frame);
    v(FieldInfo{"camera_frame", "-", 0, 0, "camera optical frame; empty: image frame id", {}},
      s.camera_frame);
    v(FieldInfo{"publish_tf", "-", 0, 1, "broadcast odom -> base_frame TF", {}}, s.publish_tf);
    v(FieldInfo{"exact_sync", "-", 0, 1, "ExactTime instead of ApproximateTime", {}}, s.exact_sync);
    v(FieldInfo{"queue_size", "-", 1, 1000, "synchroniser queue length", {}}, s.queue_size);
    v(FieldInfo{"camera_yaml", "-", 0, 0, "camera.yaml intrinsics; empty: camera_info", {}},
      s.camera_yaml);
    v(FieldInfo{"path_max_poses", "-", 1, 10000000, "poses kept in the path message", {}},
      s.path_max_poses);
    v(FieldInfo{"tf_wait_s", "s", 0.0, 60.0, "wait for the camera mount in TF at start", {}},
      s.tf_wait_s);
  }
};

}  // namespace ros_layer
}  // namespace dslam
