#pragma once
// dslam/OdometryNodelet: synchronizes colour, depth (image_transport, transports by parameter) and
// camera_info (relative, remappable names rgb/image, depth/image, rgb/camera_info), runs
// dslam::Slam on a worker thread fed by a two-frame bounded queue (it absorbs the bursts of the
// ApproximateTime synchronizer): the front end there, the back end on Slam's own thread
// (~backend_threads, the default) or after each keyframe on the worker; and publishes through
// FramePublisher, the keyframe map's outputs (corrected keyframe path, loop edges, loop status)
// through KeyFrameMapPublisher. Services: `reset` (std_srvs/Trigger), `save_trajectory` and
// `save_refined_trajectory` (dslam/SaveTrajectory).
// With map.enabled, a StaticMapper receives Slam's keyframes (on the back-end thread, or on the
// worker with ~backend_threads false) and StaticMapPublisher serves `static_map` and `save_map`.
// ObjectsPublisher tracks the moving objects on a thread of its own (the worker with
// ~backend_threads false).
//
// Threads and locks: the subscriber callbacks only queue input sets (LatestSlot) and count
// arrivals (watchdog_mutex_); the worker thread alone uses slam_ (but for RefinedPoses, below),
// publisher_, keyframe_map_publisher_, stamps_ and the camera mount; the service callbacks set
// reset_requested_ (atomic, acted on by the worker before its next frame) or take a snapshot of
// recorder_ under trajectory_mutex_ and write the files after releasing it.
// `save_refined_trajectory` reads the current segment's first stamp under trajectory_mutex_,
// releases it, then takes Slam::RefinedPoses (the map lock; Slam's getters are for any thread) and
// writes the file holding neither. The worker holds trajectory_mutex_ only to append a pose or
// start a segment, and takes no lock around Slam's calls.

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <image_transport/image_transport.h>
#include <image_transport/subscriber_filter.h>
#include <message_filters/subscriber.h>
#include <message_filters/sync_policies/approximate_time.h>
#include <message_filters/sync_policies/exact_time.h>
#include <message_filters/synchronizer.h>
#include <nodelet/nodelet.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "dslam/SaveTrajectory.h"
#include "dslam/backend/slam.h"
#include "dslam/core/camera.h"
#include "dslam/io/private_folder.h"
#include "dslam/io/trajectory_recorder.h"
#include "dslam/ros/frame_publisher.h"
#include "dslam/ros/grid_publisher.h"
#include "dslam/ros/input_checks.h"
#include "dslam/ros/keyframe_map_publisher.h"
#include "dslam/ros/latest_slot.h"
#include "dslam/ros/node_config.h"
#include "dslam/ros/objects_publisher.h"
#include "dslam/ros/static_map_publisher.h"

namespace dslam {

namespace ros_layer {

class KeyFrameMapFiles;  // dslam/ros/keyframe_map_files.h

class OdometryNodelet : public nodelet::Nodelet {
 public:
  OdometryNodelet() = default;
  /// Stops the worker thread and tears the synchronizer down before the subscribers (avoids
  /// message_filters' boost::lock_error at shutdown).
  ~OdometryNodelet() override;

 private:
  /// One synchronized input set with its wall-clock arrival time.
  struct Input {
    sensor_msgs::ImageConstPtr colour, depth;
    sensor_msgs::CameraInfoConstPtr info;
    ros::WallTime received;
  };
  using InfoSub = message_filters::Subscriber<sensor_msgs::CameraInfo>;
  using Approximate =
      message_filters::sync_policies::ApproximateTime<sensor_msgs::Image, sensor_msgs::Image,
                                                      sensor_msgs::CameraInfo>;
  using Exact = message_filters::sync_policies::ExactTime<sensor_msgs::Image, sensor_msgs::Image,
                                                          sensor_msgs::CameraInfo>;

  /// Reads and validates the parameters, starts the worker, subscribes. Throws
  /// std::runtime_error naming the parameter when one is invalid: the nodelet is then not
  /// loaded (`nodelet load` fails, dslam_odometry_node exits with status 1).
  void onInit() override;
  /// Throws std::invalid_argument naming ~image_transport or ~depth_image_transport when
  /// `transport` cannot load that transport's subscriber plugin (with the loadable ones).
  void CheckTransports(const image_transport::ImageTransport& transport) const;
  void Subscribe(ros::NodeHandle& nh);
  void WatchInputs(ros::NodeHandle& nh);
  void OnImages(const sensor_msgs::ImageConstPtr& colour, const sensor_msgs::ImageConstPtr& depth,
                const sensor_msgs::CameraInfoConstPtr& info);
  void WorkerLoop();
  void Process(const Input& input);
  /// Checks stamps and frame ids, converts the messages. Returns the problem when the set must be
  /// skipped (logged, counted, reported in `status`); warns about unusual but usable input.
  /// `backwards`: the set is older than the previous one.
  std::string ToFrame(const Input& input, RgbdFrame* frame, bool* backwards);
  /// A reset made before a frame (ResetBeforeFrame).
  enum class PreFrameReset { kNone, kService, kBackwardsInLoadedMap };
  /// Resets the odometry before the frame when the reset service asked for it (kKeepPose) or when
  /// time went `backwards` with a keyframe map loaded (kNewWorld; the odometry would otherwise
  /// start a map of its own at this frame); either way the frame then starts in the loaded map.
  /// Without a loaded map the odometry resets itself when time goes backwards.
  PreFrameReset ResetBeforeFrame(bool backwards);
  /// Keeps the frame's pose for saving; `new_world`: the odometry started a new run at the
  /// origin (time went backwards), so the pose begins a new trajectory segment.
  void RecordPose(const FrameResult& result, bool new_world);
  void Publish(const Input& input, const RgbdFrame& frame, const FrameResult& result);
  FrameCounters Counters() const;
  /// Logs each error of the work beside the frames (Slam's back end and observers, loop closing,
  /// the moving objects) once, with the part where it happened.
  void LogBackgroundErrors();
  /// The longest hold of Slam's map lock since the previous call (Slam::TakeLongestMapLockHold),
  /// kept as the minute's longest when it is.
  LockHold TakeLockHold();
  /// Once a minute of the worker's frames: logs the minute's longest map-lock hold and its holder
  /// and what the allocator holds (HeapReport), and returns glibc's free heap pages to the kernel
  /// (ReleaseFreeHeapMemory).
  void EveryMinute();
  /// The camera mount T_base_camera: from TF if available at the first frame, else the default.
  const Eigen::Isometry3d& CameraMount(const std::string& camera_frame, const ros::Time& stamp);
  bool OnReset(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  bool OnSaveTrajectory(dslam::SaveTrajectory::Request& req, dslam::SaveTrajectory::Response& res);
  /// Writes the current segment of Slam::RefinedPoses (keyframe_map_outputs.h, CurrentSegment)
  /// in TUM format; success false and the error as message when the file cannot be written.
  bool OnSaveRefinedTrajectory(dslam::SaveTrajectory::Request& req,
                               dslam::SaveTrajectory::Response& res);

  NodeConfig config_;
  // Front end and back end; used by the worker thread, and by save_refined_trajectory for the
  // getter RefinedPoses (in threaded mode Slam also runs its own back-end thread, stopped and
  // joined when slam_ is destroyed, after worker_ and the services).
  std::unique_ptr<Slam> slam_;
  std::unique_ptr<FramePublisher> publisher_;                     // used by the worker only
  std::unique_ptr<ObjectsPublisher> objects_publisher_;           // used by the worker only
  std::unique_ptr<KeyFrameMapPublisher> keyframe_map_publisher_;  // used by the worker only
  // keyframe map files: worker calls, its service (own lock; keyframe_map_files.h)
  std::unique_ptr<KeyFrameMapFiles> keyframe_maps_;
  std::shared_ptr<StaticMapper> mapper_;  // null unless map.enabled (own lock)
  // null unless backend.enabled and loop_closing.enabled (own lock; loop_closing.h)
  std::shared_ptr<LoopClosing> loop_closing_;
  std::unique_ptr<StaticMapPublisher> map_publisher_;  // timer and service (own lock)
  std::unique_ptr<GridPublisher> grid_publisher_;      // timer and service (own lock)
  std::unique_ptr<StampCheck> stamps_;                 // used by the worker only
  std::shared_ptr<const PinholeCamera> yaml_camera_;
  std::optional<Eigen::Isometry3d> T_base_camera_;

  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  std::unique_ptr<tf2_ros::StaticTransformBroadcaster> static_broadcaster_;

  std::unique_ptr<image_transport::ImageTransport> transport_;
  std::unique_ptr<image_transport::SubscriberFilter> colour_sub_, depth_sub_;
  std::unique_ptr<InfoSub> info_sub_;
  std::unique_ptr<message_filters::Synchronizer<Approximate>> approximate_sync_;
  std::unique_ptr<message_filters::Synchronizer<Exact>> exact_sync_;
  ros::ServiceServer reset_srv_, save_srv_, save_refined_srv_;
  ros::WallTimer watchdog_timer_;

  std::mutex watchdog_mutex_;
  std::unique_ptr<InputWatchdog> watchdog_;  // guarded by watchdog_mutex_

  LatestSlot<Input> slot_;
  std::thread worker_;
  std::atomic<uint64_t> received_{0}, processed_{0}, rejected_{0};
  std::atomic<bool> reset_requested_{false};
  // TakeLockHold's and EveryMinute's state; the worker's alone
  ros::WallTime minute_start_;
  LockHold minute_hold_;
  double map_lock_max_ms_ = 0.0;  // of the frame being published

  std::mutex trajectory_mutex_;
  /// Holds the recorder's files when ~trajectory_stream is empty (declared before recorder_,
  /// so that it is removed after the recorder closed them).
  std::unique_ptr<PrivateFolder> trajectory_folder_;
  std::unique_ptr<TrajectoryRecorder> recorder_;  // every tracked pose, guarded
  /// [s] stamp of the current segment's first tracked frame (none yet: empty), guarded
  std::optional<double> segment_first_stamp_s_;
};

}  // namespace ros_layer
}  // namespace dslam
