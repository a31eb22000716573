#include "dslam/ros/odometry_nodelet.h"

#include <tf2_eigen/tf2_eigen.h>
#include <pluginlib/class_list_macros.hpp>

#include "dslam/io/dataset_io.h"
#include "dslam/ros/conversions.h"
#include "dslam/ros/param_loader.h"

namespace dslam {
namespace ros_layer {

OdometryNodelet::~OdometryNodelet() {
  // message_filters throws boost::lock_error when a filter is destroyed while a synchronizer
  // connected to it still exists: destroy the synchronizers first, then the filters.
  approximate_sync_.reset();
  exact_sync_.reset();
  for (auto* sub : {colour_sub_.get(), depth_sub_.get()}) {
    if (sub) sub->unsubscribe();
  }
  if (info_sub_) info_sub_->unsubscribe();
  slot_.Close();
  if (worker_.joinable()) worker_.join();
}

void OdometryNodelet::onInit() {
  ros::NodeHandle& nh = getNodeHandle();
  ros::NodeHandle& pnh = getPrivateNodeHandle();
  Config config;
  try {
    LoadRosParams(pnh, &config, &config_);
    if (!config_.camera_yaml.empty()) yaml_camera_ = LoadCameraYaml(config_.camera_yaml).camera;
    slam_ = std::make_unique<Slam>(
        config, config_.backend_threads ? BackEndMode::kThreaded : BackEndMode::kSynchronous);
  } catch (const std::exception& e) {
    NODELET_FATAL("dslam: invalid parameters, not starting: %s", e.what());
    return;
  }
  publisher_ = std::make_unique<FramePublisher>(nh, config_);
  tf_buffer_ = std::make_unique<tf2_ros::Buffer>();
  tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_, nh);
  static_broadcaster_ = std::make_unique<tf2_ros::StaticTransformBroadcaster>();
  reset_srv_ = nh.advertiseService("reset", &OdometryNodelet::OnReset, this);
  save_srv_ = nh.advertiseService("save_trajectory", &OdometryNodelet::OnSaveTrajectory, this);
  worker_ = std::thread(&OdometryNodelet::WorkerLoop, this);
  Subscribe(nh);
}

void OdometryNodelet::Subscribe(ros::NodeHandle& nh) {
  const int q = config_.queue_size;
  colour_sub_ = std::make_unique<ImageSub>(nh, "rgb/image", q);
  depth_sub_ = std::make_unique<ImageSub>(nh, "depth/image", q);
  info_sub_ = std::make_unique<InfoSub>(nh, "rgb/camera_info", q);
  if (config_.exact_sync) {
    exact_sync_ = std::make_unique<message_filters::Synchronizer<Exact>>(Exact(q), *colour_sub_,
                                                                         *depth_sub_, *info_sub_);
    exact_sync_->registerCallback(&OdometryNodelet::OnImages, this);
  } else {
    approximate_sync_ = std::make_unique<message_filters::Synchronizer<Approximate>>(
        Approximate(q), *colour_sub_, *depth_sub_, *info_sub_);
    approximate_sync_->registerCallback(&OdometryNodelet::OnImages, this);
  }
  NODELET_INFO("dslam: waiting for %s, %s, %s (%s sync, queue %d)", colour_sub_->getTopic().c_str(),
               depth_sub_->getTopic().c_str(), info_sub_->getTopic().c_str(),
               config_.exact_sync ? "exact" : "approximate", q);
}

void OdometryNodelet::OnImages(const sensor_msgs::ImageConstPtr& colour,
                               const sensor_msgs::ImageConstPtr& depth,
                               const sensor_msgs::CameraInfoConstPtr& info) {
  ++received_;
  if (slot_.Put(Input{colour, depth, info, ros::WallTime::now()})) {
    NODELET_WARN_THROTTLE(5.0, "dslam: processing slower than input: %lu frames dropped so far",
                          static_cast<unsigned long>(slot_.dropped()));
  }
}

void OdometryNodelet::WorkerLoop() {
  while (std::optional<Input> input = slot_.Take()) {
    try {
      Process(*input);
    } catch (const std::exception& e) {
      ++rejected_;
      NODELET_ERROR_THROTTLE(1.0, "dslam: frame skipped: %s", e.what());
    }
  }
}

bool OdometryNodelet::ToFrame(const Input& input, RgbdFrame* frame) {
  try {
    frame->stamp_s = input.colour->header.stamp.toSec();
    frame->colour = ColourFromImage(*input.colour);
    frame->depth_m = DepthFromImage(*input.depth);
    frame->camera = yaml_camera_
                        ? yaml_camera_
                        : CameraFromInfo(*input.info, *input.colour,
                                         config_.rectified_input ? ImageGeometry::kRectified
                                                                 : ImageGeometry::kRaw);
  } catch (const std::exception& e) {
    NODELET_ERROR_THROTTLE(1.0, "dslam: bad input, frame skipped: %s", e.what());
    return false;
  }
  const std::string problem = frame->Check();
  if (!problem.empty()) {
    NODELET_ERROR_THROTTLE(1.0, "dslam: bad input, frame skipped: %s (colour %ux%u, depth %ux%u)",
                           problem.c_str(), input.colour->width, input.colour->height,
                           input.depth->width, input.depth->height);
    return false;
  }
  return true;
}

void OdometryNodelet::Process(const Input& input) {
  RgbdFrame frame;
  if (!ToFrame(input, &frame)) {
    ++rejected_;
    return;
  }
  if (reset_requested_.exchange(false)) {
    slam_->Reset();
    publisher_->ClearPath();
  }
  const FrameResult result = slam_->ProcessFrame(frame);
  ++processed_;
  if (result.reset) {
    NODELET_WARN("dslam: odometry reset: %s", result.message.c_str());
    std::lock_guard<std::mutex> lock(trajectory_mutex_);
    trajectory_.clear();
  }
  if (result.has_pose) {
    std::lock_guard<std::mutex> lock(trajectory_mutex_);
    trajectory_.push_back({result.stamp_s, result.T_world_camera});
  }
  std_msgs::Header header = input.colour->header;
  header.frame_id =
      NormaliseFrameId(config_.camera_frame.empty() ? header.frame_id : config_.camera_frame);
  const Eigen::Isometry3d& T_base_camera = CameraMount(header.frame_id, header.stamp);
  const FrameCounters counters{received_.load(), processed_.load(), slot_.dropped(),
                               rejected_.load()};
  const double latency_ms = (ros::WallTime::now() - input.received).toSec() * 1e3;
  publisher_->Publish(result, frame, header, T_base_camera, counters, latency_ms);
}

const Eigen::Isometry3d& OdometryNodelet::CameraMount(const std::string& camera_frame,
                                                      const ros::Time& stamp) {
  if (T_base_camera_) return *T_base_camera_;
  std::string error;
  if (!camera_frame.empty() &&
      tf_buffer_->canTransform(config_.base_frame, camera_frame, ros::Time(0),
                               ros::Duration(config_.tf_wait_s), &error)) {
    T_base_camera_ = tf2::transformToEigen(
        tf_buffer_->lookupTransform(config_.base_frame, camera_frame, ros::Time(0)));
    NODELET_INFO("dslam: camera mount %s <- %s from TF", config_.base_frame.c_str(),
                 camera_frame.c_str());
    return *T_base_camera_;
  }
  T_base_camera_ = DefaultBaseFromOptical();
  NODELET_INFO("dslam: no TF %s <- %s; using the default mount (optical z = base x)%s",
               config_.base_frame.c_str(), camera_frame.c_str(),
               config_.publish_tf ? " and publishing it" : "");
  if (config_.publish_tf && !camera_frame.empty()) {
    geometry_msgs::TransformStamped tf = tf2::eigenToTransform(*T_base_camera_);
    tf.header.stamp = stamp;
    tf.header.frame_id = config_.base_frame;
    tf.child_frame_id = camera_frame;
    static_broadcaster_->sendTransform(tf);
  }
  return *T_base_camera_;
}

bool OdometryNodelet::OnReset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  reset_requested_ = true;
  {
    std::lock_guard<std::mutex> lock(trajectory_mutex_);
    trajectory_.clear();
  }
  res.success = true;
  res.message = "odometry resets before the next frame";
  return true;
}

bool OdometryNodelet::OnSaveTrajectory(dslam::SaveTrajectory::Request& req,
                                       dslam::SaveTrajectory::Response& res) {
  std::lock_guard<std::mutex> lock(trajectory_mutex_);
  try {
    WriteTumTrajectory(req.path, trajectory_);
    res.success = true;
    res.poses = static_cast<int>(trajectory_.size());
    res.message = "wrote " + std::to_string(trajectory_.size()) + " poses to " + req.path;
  } catch (const std::exception& e) {
    res.success = false;
    res.message = e.what();
  }
  return true;
}

}  // namespace ros_layer
}  // namespace dslam

PLUGINLIB_EXPORT_CLASS(dslam::ros_layer::OdometryNodelet, nodelet::Nodelet)
