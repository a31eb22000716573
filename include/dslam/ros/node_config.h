#pragma once
// Parameters of the ROS layer (the odometry nodelet's own ~keys), described with the same
// FieldInfo visitor as the core Config sections so that one loader reads and checks both.

#include <string>

#include "dslam/core/config_field.h"

namespace dslam {
namespace ros_layer {

/// Top-level private parameters of dslam/OdometryNodelet (~odom_frame, ~queue_size, ...). Each
/// field's unit, range and meaning are given in Fields(), the one source: docs/parameters.md's
/// table of the ROS layer is generated from it (DescribeNodeConfigMarkdown, a test checks it).
struct NodeConfig {
  std::string odom_frame = "odom";
  std::string map_frame = "map";
  std::string base_frame = "base_link";
  std::string camera_frame = "";
  bool publish_tf = true;
  bool publish_map_tf = true;
  bool exact_sync = false;
  int queue_size = 10;
  std::string camera_yaml = "";
  bool rectified_input = false;
  int path_max_poses = 10000;
  double path_rate_hz = 2.0;
  std::string trajectory_stream = "";
  std::string image_transport = "raw";
  std::string depth_image_transport = "raw";
  double input_timeout_s = 5.0;
  double tf_wait_s = 0.0;
  bool backend_threads = true;
  double static_map_rate_hz = 1.0;
  std::string keyframe_map = "";
  bool localisation_only = false;
  double localise_timeout_s = 10.0;
  std::string save_keyframe_map_on_exit = "";
  bool keyframe_map_images = false;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    v(Field("odom_frame", "-", 0, 0,
            "continuous odometry frame (REP 105): odom topic, odom_frame -> base_frame TF"),
      s.odom_frame);
    v(Field("map_frame", "-", 0, 0,
            "the tracker's world (REP 105 map: the base frame at the first frame); map_frame -> "
            "odom_frame takes the back end's corrections and relocalisation jumps"),
      s.map_frame);
    v(Field("base_frame", "-", 0, 0, "robot body frame, x forward, z up (REP 103)"), s.base_frame);
    v(Field("camera_frame", "-", 0, 0, "colour camera optical frame; empty: image frame id"),
      s.camera_frame);
    v(Flag("publish_tf",
           "broadcast odom_frame -> base_frame TF (and the default mount when TF has none)"),
      s.publish_tf);
    v(Flag("publish_map_tf",
           "broadcast map_frame -> odom_frame TF and publish the data of the tracker's world "
           "(clouds, graph markers, moving objects, static map, path) in map_frame; false where "
           "another localiser owns map -> odom: our map_frame is then not in TF, so that data "
           "goes out in odom_frame (moved by the tracker's map -> odom at the frame)"),
      s.publish_map_tf);
    v(Flag("exact_sync", "ExactTime instead of ApproximateTime"), s.exact_sync);
    v(Field("queue_size", "-", 1, 1000, "synchroniser queue length per input"), s.queue_size);
    v(Field("camera_yaml", "-", 0, 0, "camera.yaml with calibrated intrinsics; empty: camera_info"),
      s.camera_yaml);
    v(Flag("rectified_input",
           "the colour and depth topics are rectified (image_rect*): intrinsics from camera_info "
           "P, no distortion (image_pipeline's convention); false: raw images, K and D (TUM "
           "bags, tum_to_bag)"),
      s.rectified_input);
    v(Field("path_max_poses", "-", 1, 10000000, "poses kept in the path message (a ring)"),
      s.path_max_poses);
    v(Field("path_rate_hz", "Hz", 0.01, 1000.0,
            "highest rate at which the path is published (each message carries the whole ring)"),
      s.path_rate_hz);
    v(Field("trajectory_stream", "-", 0, 0,
            "file to which every tracked pose is appended (and flushed) as it goes (TUM format), "
            "keeping none in memory; earlier segments are renamed to <stem>.seg<N><ext> beside "
            "it, and save_trajectory copies these files; empty: the same in a private folder under "
            "$TMPDIR (else /tmp), removed at exit, so that memory stays flat. Relative "
            "paths are relative to the node's working directory (ROS_HOME under roslaunch)"),
      s.trajectory_stream);
    v(Field("image_transport", "-", 0, 0,
            "image_transport of the colour image (raw, compressed, ...)"),
      s.image_transport);
    v(Field("depth_image_transport", "-", 0, 0,
            "image_transport of the depth image (raw, compressedDepth, ...)"),
      s.depth_image_transport);
    v(Field("input_timeout_s", "s", 0.1, 3600.0,
            "when images arrive but no synchronized set is formed for this long, a warning names "
            "the missing input (or the stamps that never match)"),
      s.input_timeout_s);
    v(Field("tf_wait_s", "s", 0.0, 60.0,
            "wait at the first frame for base_frame <- camera frame (the mount) in TF"),
      s.tf_wait_s);
    v(Flag("backend_threads",
           "back end (backend.enabled; also the static map's fusion, with the back end off too) "
           "and moving objects each on a thread of their own beside tracking (objects frame by "
           "frame in order); false: both on the worker thread (synchronous)"),
      s.backend_threads);
    v(Field("static_map_rate_hz", "Hz", 0.01, 100.0,
            "highest rate at which static_map is rebuilt and published (map.enabled; only while "
            "subscribed and changed)"),
      s.static_map_rate_hz);
    v(Field("keyframe_map", "-", 0, 0,
            "keyframe map file (save_keyframe_map, dslam_run_dataset --save-keyframe-map) to "
            "start in: no pose (status 'localising') until a frame is relocalised in it, then "
            "every pose in its world (its first run's first frame); the map is extended (not with "
            "localisation_only). A file that cannot be read or has another camera, vocabulary, "
            "ORB settings or depth noise model is refused with the reason and the node maps "
            "from scratch; empty: none"),
      s.keyframe_map);
    v(Flag("localisation_only",
           "track in keyframe_map without changing it: its keyframes and points are never moved, "
           "erased or relabelled, keyframes made meanwhile are dropped once they leave the "
           "window, and save_keyframe_map writes the loaded map unchanged; the node never leaves "
           "the loaded map (no localise_timeout_s, no re-initialisation). Needs keyframe_map (the "
           "node refuses to start without); false: the loaded map is extended"),
      s.localisation_only);
    v(Field("localise_timeout_s", "s", 0.1, 3600.0,
            "without a frame localised in keyframe_map this long after the first, a new map "
            "starts (a new trajectory segment, as when time goes backwards); not with "
            "localisation_only"),
      s.localise_timeout_s);
    v(Field("save_keyframe_map_on_exit", "-", 0, 0,
            "keyframe map file written when the node shuts down (a file already there is kept "
            "as PATH.prev); empty: none"),
      s.save_keyframe_map_on_exit);
    v(Flag("keyframe_map_images",
           "keep each map keyframe's colour and depth (about 2 MB per 640x480 keyframe, up to "
           "tracking.max_keyframes of them) so that saved keyframe maps carry them and a node "
           "that loads one re-fuses its static map; false: maps are saved without images"),
      s.keyframe_map_images);
  }
};

/// The frame in which the data of the tracker's world (clouds, graph markers, moving objects,
/// static map, path) is published: map_frame with publish_map_tf, else odom_frame.
inline const std::string& WorldDataFrameId(const NodeConfig& config) {
  return config.publish_map_tf ? config.map_frame : config.odom_frame;
}

/// The Markdown table of every NodeConfig parameter (name with `~`, default, unit, range,
/// meaning) at its default, as docs/parameters.md shows it (dslam_node_params_doc prints it).
std::string DescribeNodeConfigMarkdown();

}  // namespace ros_layer
}  // namespace dslam
