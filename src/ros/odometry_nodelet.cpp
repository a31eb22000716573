// OdometryNodelet: start-up, subscriptions, the input watchdog and the services. The worker
// thread's processing is in odometry_worker.cpp.
#include "dslam/ros/odometry_nodelet.h"

#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include <pluginlib/class_list_macros.hpp>

#include "dslam/io/dataset_io.h"
#include "dslam/io/private_folder.h"
#include "dslam/io/trajectory_io.h"
#include "dslam/loop_closing/loop_closing.h"
#include "dslam/place_recognition/vocabulary.h"
#include "dslam/ros/keyframe_map_files.h"
#include "dslam/ros/keyframe_map_outputs.h"
#include "dslam/ros/param_loader.h"
#include "dslam/ros/service_reply.h"

namespace dslam {
namespace ros_layer {

OdometryNodelet::~OdometryNodelet() {
  // message_filters throws boost::lock_error when a filter is destroyed while a synchronizer
  // connected to it still exists: destroy the synchronizers first, then the filters.
  watchdog_timer_.stop();
  approximate_sync_.reset();
  exact_sync_.reset();
  for (auto* sub : {colour_sub_.get(), depth_sub_.get()}) {
    if (sub) sub->unsubscribe();
  }
  if (info_sub_) info_sub_->unsubscribe();
  slot_.Close();
  if (worker_.joinable()) worker_.join();
  if (keyframe_maps_ && slam_) {
    slam_->WaitForBackEnd();
    if (loop_closing_) loop_closing_->Wait();
    slam_->WaitForBackEnd();       // the last loop's correction reaches the observers
    keyframe_maps_->SaveOnExit();  // logs its own error
    LogBackgroundErrors();
  }
  map_publisher_.reset();  // stops its timer and service (the worker used it until now)
  grid_publisher_.reset();
}

namespace {

/// Keeps freed per-frame buffers in the process: each frame's converted colour and depth images
/// (0.9 and 1.2 MB at 640x480) are allocated on the worker thread and freed a frame later;
/// glibc's defaults hand such memory back to the kernel (mmap above a 128 kB threshold, heap
/// trimming above 128 kB), and every page of the next frame's images is faulted in again.
/// Measured on the Bonn segment at 30 Hz (2-core VM): the conversions took 5.0 + 8.9 ms per
/// frame (median) with the defaults and 0.23 + 0.39 ms with these settings (receive-to-publish
/// latency median 28.1 -> 13.2 ms, BENCHMARKS.md "ROS node"); the free memory kept at the top of
/// each heap is bounded by the trim threshold. glibc's malloc only: under jemalloc mallopt
/// changes nothing, and jemalloc keeps freed pages for reuse and returns them after its decay
/// time by itself.
void KeepPerFrameBuffers() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // the largest glibc accepts on 64-bit
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
}

}  // namespace

void OdometryNodelet::onInit() {
  KeepPerFrameBuffers();
  ros::NodeHandle& nh = getNodeHandle();
  ros::NodeHandle& pnh = getPrivateNodeHandle();
  Config config;
  try {
    LoadRosParams(pnh, &config, &config_);
    transport_ = std::make_unique<image_transport::ImageTransport>(nh);
    CheckTransports(*transport_);
    if (!config_.camera_yaml.empty()) yaml_camera_ = LoadCameraYaml(config_.camera_yaml).camera;
    // Without ~trajectory_stream the poses still go to a file, a private one removed at exit,
    // so that memory stays flat however long the node runs.
    std::string stream = config_.trajectory_stream;
    if (stream.empty()) {
      trajectory_folder_ = std::make_unique<PrivateFolder>("dslam-trajectory-");
      stream = trajectory_folder_->path() + "/trajectory.txt";
    }
    recorder_ = std::make_unique<TrajectoryRecorder>(stream);
    std::vector<std::shared_ptr<KeyFrameObserver>> observers;
    if (config.map.enabled) observers.push_back(mapper_ = std::make_shared<StaticMapper>(config));
    // Loop closing and keyframe map files (their places and identity) share the vocabulary.
    const auto vocabulary =
        std::make_shared<const Vocabulary>(Vocabulary::Load(DefaultVocabularyPath()));
    if (config.backend.enabled && config.loop_closing.enabled) {  // it needs the keyframe map
      loop_closing_ = std::make_shared<LoopClosing>(
          config, vocabulary,
          config_.backend_threads ? WorkerMode::kThreaded : WorkerMode::kSynchronous);
      observers.push_back(loop_closing_);
    }
    keyframe_maps_ = std::make_unique<KeyFrameMapFiles>(nh, config_, vocabulary);
    for (auto& observer : keyframe_maps_->Observers()) observers.push_back(observer);
    slam_ = std::make_unique<Slam>(
        config, config_.backend_threads ? BackEndMode::kThreaded : BackEndMode::kSynchronous,
        // For save_refined_trajectory: per tracked frame its pose on its keyframe (40 bytes;
        // RefinedTrajectory), per keyframe its latest pose.
        RefinedPoseRecording::kOn, observers);
    if (loop_closing_) loop_closing_->Attach(slam_.get());
    keyframe_maps_->Attach(slam_.get());
  } catch (const std::exception& e) {
    NODELET_FATAL("dslam: invalid parameters, not starting: %s", e.what());
    throw std::runtime_error(std::string("dslam: invalid parameters: ") + e.what());
  }
  stamps_ = std::make_unique<StampCheck>(config.tracking.max_prediction_gap_s);
  publisher_ = std::make_unique<FramePublisher>(nh, config_);
  objects_publisher_ = std::make_unique<ObjectsPublisher>(
      nh, slam_->config(),
      config_.backend_threads ? WorkerMode::kThreaded : WorkerMode::kSynchronous);
  keyframe_map_publisher_ = std::make_unique<KeyFrameMapPublisher>(nh, *slam_, loop_closing_);
  if (mapper_) {
    map_publisher_ = std::make_unique<StaticMapPublisher>(nh, config_, mapper_,
                                                          slam_->config().map.voxel_size_m);
    grid_publisher_ = std::make_unique<GridPublisher>(nh, config_, slam_->config(), mapper_);
  }
  tf_buffer_ = std::make_unique<tf2_ros::Buffer>();
  tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_, nh);
  static_broadcaster_ = std::make_unique<tf2_ros::StaticTransformBroadcaster>();
  reset_srv_ = nh.advertiseService("reset", &OdometryNodelet::OnReset, this);
  save_srv_ = nh.advertiseService("save_trajectory", &OdometryNodelet::OnSaveTrajectory, this);
  save_refined_srv_ = nh.advertiseService("save_refined_trajectory",
                                          &OdometryNodelet::OnSaveRefinedTrajectory, this);
  worker_ = std::thread(&OdometryNodelet::WorkerLoop, this);
  Subscribe(nh);
  WatchInputs(nh);
}

void OdometryNodelet::CheckTransports(const image_transport::ImageTransport& transport) const {
  const std::vector<std::string> loadable = transport.getLoadableTransports();
  std::string names;
  for (const std::string& name : loadable) names += (names.empty() ? "" : ", ") + name;
  for (const auto& [key, value] :
       {std::make_pair("image_transport", config_.image_transport),
        std::make_pair("depth_image_transport", config_.depth_image_transport)}) {
    const std::string wanted = "image_transport/" + value;
    if (std::find(loadable.begin(), loadable.end(), wanted) == loadable.end()) {
      throw std::invalid_argument(std::string("~") + key + " '" + value +
                                  "' has no plugin on this system (loadable: " + names + ")");
    }
  }
}

void OdometryNodelet::Subscribe(ros::NodeHandle& nh) {
  const int q = config_.queue_size;
  // As image_pipeline: the transport of each image by a parameter (read here from config_, which
  // LoadRosParams checked), e.g. compressed colour and compressedDepth depth.
  colour_sub_ = std::make_unique<image_transport::SubscriberFilter>(
      *transport_, "rgb/image", q, image_transport::TransportHints(config_.image_transport));
  depth_sub_ = std::make_unique<image_transport::SubscriberFilter>(
      *transport_, "depth/image", q,
      image_transport::TransportHints(config_.depth_image_transport));
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
  NODELET_INFO("dslam: waiting for %s (%s), %s (%s), %s (%s sync, queue %d)",
               colour_sub_->getTopic().c_str(), config_.image_transport.c_str(),
               depth_sub_->getTopic().c_str(), config_.depth_image_transport.c_str(),
               info_sub_->getTopic().c_str(), config_.exact_sync ? "exact" : "approximate", q);
}

void OdometryNodelet::WatchInputs(ros::NodeHandle& nh) {
  watchdog_ = std::make_unique<InputWatchdog>(std::array<std::string, 3>{
      colour_sub_->getTopic(), depth_sub_->getTopic(), info_sub_->getTopic()});
  const auto count = [this](InputWatchdog::Input input) {
    return [this, input](const auto& msg) {
      const std::lock_guard<std::mutex> lock(watchdog_mutex_);
      watchdog_->Arrived(input, msg->header.stamp.toSec());
    };
  };
  colour_sub_->registerCallback(
      std::function<void(const sensor_msgs::ImageConstPtr&)>(count(InputWatchdog::kColour)));
  depth_sub_->registerCallback(
      std::function<void(const sensor_msgs::ImageConstPtr&)>(count(InputWatchdog::kDepth)));
  info_sub_->registerCallback(
      std::function<void(const sensor_msgs::CameraInfoConstPtr&)>(count(InputWatchdog::kInfo)));
  watchdog_timer_ = nh.createWallTimer(ros::WallDuration(config_.input_timeout_s),
                                       [this](const ros::WallTimerEvent&) {
                                         std::string warning;
                                         {
                                           const std::lock_guard<std::mutex> lock(watchdog_mutex_);
                                           warning = watchdog_->Check();
                                         }
                                         if (!warning.empty())
                                           NODELET_WARN("dslam: %s", warning.c_str());
                                       });
}

void OdometryNodelet::OnImages(const sensor_msgs::ImageConstPtr& colour,
                               const sensor_msgs::ImageConstPtr& depth,
                               const sensor_msgs::CameraInfoConstPtr& info) {
  ++received_;
  {
    const std::lock_guard<std::mutex> lock(watchdog_mutex_);
    watchdog_->Synchronized();
  }
  if (slot_.Put(Input{colour, depth, info, ros::WallTime::now()})) {
    NODELET_WARN_THROTTLE(5.0, "dslam: processing slower than input: %lu frames dropped so far",
                          static_cast<unsigned long>(slot_.dropped()));
  }
}

bool OdometryNodelet::OnReset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  reset_requested_ = true;  // the worker resets before its next frame: no frame is in between
  res.success = true;
  res.message = keyframe_maps_->HasLoadedMap()
                    ? "odometry resets before the next frame and starts localising in the loaded "
                      "keyframe map again (no pose until a frame is relocalised in it)"
                    : "odometry resets before the next frame and re-initialises at the last pose "
                      "(odom stays continuous)";
  return true;
}

bool OdometryNodelet::OnSaveTrajectory(dslam::SaveTrajectory::Request& req,
                                       dslam::SaveTrajectory::Response& res) {
  TrajectorySnapshot snapshot;
  int segments = 0;
  try {
    {
      const std::lock_guard<std::mutex> lock(trajectory_mutex_);  // the worker waits only here
      snapshot = recorder_->Snapshot();
      segments = recorder_->num_segments();
    }
    res.poses = static_cast<int>(WriteTrajectorySnapshot(snapshot, req.path));
    res.success = true;
    res.message = "wrote " + std::to_string(res.poses) + " poses to " + req.path;
    if (segments > 1) {
      res.message += " (current segment; " + std::to_string(segments - 1) +
                     " earlier segment(s) beside it as " + SegmentPath(req.path, 1) + ", ...)";
    }
  } catch (const std::exception& e) {
    res.success = false;
    res.message = e.what();
  }
  return true;
}

bool OdometryNodelet::OnSaveRefinedTrajectory(dslam::SaveTrajectory::Request& req,
                                              dslam::SaveTrajectory::Response& res) {
  std::optional<double> first_stamp_s;
  {
    const std::lock_guard<std::mutex> lock(trajectory_mutex_);
    first_stamp_s = segment_first_stamp_s_;
  }
  return AnswerWrite(res, [&] {
    // The map lock only while RefinedPoses copies its blocks; the file is written after it.
    double lock_held_ms = 0.0;
    const Trajectory segment =
        first_stamp_s ? CurrentSegment(slam_->RefinedPoses(&lock_held_ms), *first_stamp_s)
                      : Trajectory();
    WriteTumTrajectory(req.path, segment);
    res.poses = static_cast<int>(segment.size());
    char held[64];
    std::snprintf(held, sizeof(held), " (map lock held %.3f ms)", lock_held_ms);
    return "wrote " + std::to_string(res.poses) + " refined poses of the current segment to " +
           req.path + held;
  });
}

}  // namespace ros_layer
}  // namespace dslam

PLUGINLIB_EXPORT_CLASS(dslam::ros_layer::OdometryNodelet, nodelet::Nodelet)
