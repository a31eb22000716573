#pragma once
// dslam/OdometryNodelet: synchronizes colour, depth and camera_info (relative, remappable names
// rgb/image, depth/image, rgb/camera_info), runs dslam::Slam on a worker thread fed by a
// two-frame bounded queue (it absorbs the bursts of the ApproximateTime synchronizer): the front
// end there, the back end on Slam's own thread (~backend_threads, the default) or after each
// keyframe on the worker; and publishes through FramePublisher. Services: `reset`
// (std_srvs/Trigger), `save_trajectory` (dslam/SaveTrajectory).

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

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
#include "dslam/io/trajectory_io.h"
#include "dslam/ros/frame_publisher.h"
#include "dslam/ros/latest_slot.h"
#include "dslam/ros/node_config.h"

namespace dslam {
namespace ros_layer {

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
  using ImageSub = message_filters::Subscriber<sensor_msgs::Image>;
  using InfoSub = message_filters::Subscriber<sensor_msgs::CameraInfo>;
  using Approximate =
      message_filters::sync_policies::ApproximateTime<sensor_msgs::Image, sensor_msgs::Image,
                                                      sensor_msgs::CameraInfo>;
  using Exact = message_filters::sync_policies::ExactTime<sensor_msgs::Image, sensor_msgs::Image,
                                                          sensor_msgs::CameraInfo>;

  void onInit() override;
  void Subscribe(ros::NodeHandle& nh);
  void OnImages(const sensor_msgs::ImageConstPtr& colour, const sensor_msgs::ImageConstPtr& depth,
                const sensor_msgs::CameraInfoConstPtr& info);
  void WorkerLoop();
  void Process(const Input& input);
  /// Converts the messages; logs a throttled error and returns false on bad input.
  bool ToFrame(const Input& input, RgbdFrame* frame);
  /// The camera mount T_base_camera: from TF if available at the first frame, else the default.
  const Eigen::Isometry3d& CameraMount(const std::string& camera_frame, const ros::Time& stamp);
  bool OnReset(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  bool OnSaveTrajectory(dslam::SaveTrajectory::Request& req, dslam::SaveTrajectory::Response& res);

  NodeConfig config_;
  // Front end and back end; used by the worker thread only (in threaded mode Slam also runs its
  // own back-end thread, stopped and joined when slam_ is destroyed, after worker_).
  std::unique_ptr<Slam> slam_;
  std::unique_ptr<FramePublisher> publisher_;  // used by the worker only
  std::shared_ptr<const PinholeCamera> yaml_camera_;
  std::optional<Eigen::Isometry3d> T_base_camera_;

  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  std::unique_ptr<tf2_ros::StaticTransformBroadcaster> static_broadcaster_;

  std::unique_ptr<ImageSub> colour_sub_, depth_sub_;
  std::unique_ptr<InfoSub> info_sub_;
  std::unique_ptr<message_filters::Synchronizer<Approximate>> approximate_sync_;
  std::unique_ptr<message_filters::Synchronizer<Exact>> exact_sync_;
  ros::ServiceServer reset_srv_, save_srv_;

  LatestSlot<Input> slot_;
  std::thread worker_;
  std::atomic<uint64_t> received_{0}, processed_{0}, rejected_{0};
  std::atomic<bool> reset_requested_{false};

  std::mutex trajectory_mutex_;
  Trajectory trajectory_;  // every tracked frame since the last reset, guarded
};

}  // namespace ros_layer
}  // namespace dslam
