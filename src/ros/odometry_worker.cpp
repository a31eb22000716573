// OdometryNodelet's worker thread: input checks and conversion, resets, the odometry, the
// recorded trajectory and publication (the nodelet's set-up and services: odometry_nodelet.cpp).
#include <tf2_eigen/tf2_eigen.h>

#include "dslam/ros/conversions.h"
#include "dslam/ros/heap_report.h"
#include "dslam/ros/keyframe_map_files.h"
#include "dslam/ros/odometry_nodelet.h"

namespace dslam {
namespace ros_layer {

void OdometryNodelet::WorkerLoop() {
  while (std::optional<Input> input = slot_.Take()) {
    try {
      Process(*input);
    } catch (const std::exception& e) {
      ++rejected_;
      NODELET_ERROR_THROTTLE(1.0, "dslam: frame skipped: %s", e.what());
    }
    LogBackgroundErrors();
  }
}

LockHold OdometryNodelet::TakeLockHold() {
  const LockHold hold = slam_->TakeLongestMapLockHold();
  if (hold.ms > minute_hold_.ms) minute_hold_ = hold;
  return hold;
}

void OdometryNodelet::EveryMinute() {
  const ros::WallTime now = ros::WallTime::now();
  if (minute_start_.isZero()) minute_start_ = now;
  if ((now - minute_start_).toSec() < 60.0) return;
  minute_start_ = now;
  NODELET_INFO("dslam: longest map-lock hold in the last minute: %.2f ms (%s)", minute_hold_.ms,
               minute_hold_.where);
  minute_hold_ = LockHold();
  NODELET_INFO("dslam: %s", HeapReport().c_str());
  // With glibc's malloc (a nodelet manager started without jemalloc) the free pages go back to
  // the kernel here: KeepPerFrameBuffers keeps up to its trim threshold free in each arena, and
  // with an arena per thread the resident size crept while the heap stayed flat (heaptrack: heap
  // 108-124 MB from minute 2 to 5 of the long run, VmRSS +1.6 MB a minute). Under jemalloc
  // (dslam_odometry_node, dslam.launch's manager) this does nothing.
  ReleaseFreeHeapMemory();
}

void OdometryNodelet::LogBackgroundErrors() {
  std::vector<ReportedError> errors = slam_->errors()->TakeNew();
  if (loop_closing_) {
    for (ReportedError& error : loop_closing_->errors()->TakeNew()) errors.push_back(error);
  }
  for (ReportedError& error : objects_publisher_->errors().TakeNew()) errors.push_back(error);
  for (const ReportedError& error : errors) {
    NODELET_ERROR("dslam: error in %s: %s", error.where.c_str(), error.what.c_str());
  }
}

void OdometryNodelet::Process(const Input& input) {
  RgbdFrame frame;
  bool backwards = false;
  const std::string problem = ToFrame(input, &frame, &backwards);
  if (!problem.empty()) {
    ++rejected_;
    NODELET_ERROR_THROTTLE(1.0, "dslam: bad input, frame skipped: %s", problem.c_str());
    const double latency_ms = (ros::WallTime::now() - input.received).toSec() * 1e3;
    publisher_->PublishRejected(problem, input.colour->header, Counters(), latency_ms);
    return;
  }
  const PreFrameReset pre_reset = ResetBeforeFrame(backwards);
  keyframe_maps_->BeforeFrame(frame.camera);
  FrameRequest request;
  request.points = publisher_->WantsPoints() || objects_publisher_->Wanted();
  request.edges = publisher_->WantsEdges();
  const bool was_localising = slam_->Localising();
  FrameResult result = slam_->ProcessFrame(frame, request);
  map_lock_max_ms_ = TakeLockHold().ms;
  EveryMinute();
  keyframe_maps_->AfterFrame(result, was_localising);
  ++processed_;
  if (pre_reset == PreFrameReset::kBackwardsInLoadedMap) {
    result.reset = true;
    result.message = "time went backwards: reset: localising in the loaded keyframe map";
  }
  const bool new_world = result.reset;  // time went backwards (the odometry's reset or ours)
  if (new_world) {
    NODELET_WARN(
        "dslam: odometry reset (%s): new run (odom and map -> odom restart at the identity), new "
        "trajectory segment",
        result.message.c_str());
    publisher_->StartNewRun();
  }
  if (pre_reset == PreFrameReset::kService) {
    result.reset = true;
    result.message = keyframe_maps_->HasLoadedMap()
                         ? "reset by the reset service: localising in the loaded keyframe map"
                         : "reset by the reset service: re-initialised at the last pose";
  }
  if (result.state == TrackingState::kLost) {
    NODELET_WARN_THROTTLE(2.0, "dslam: tracking lost: %s", result.message.c_str());
  }
  RecordPose(result, new_world);
  Publish(input, frame, result);
}

std::string OdometryNodelet::ToFrame(const Input& input, RgbdFrame* frame, bool* backwards) {
  const StampVerdict stamp = stamps_->Check(input.colour->header.stamp.toSec());
  if (!stamp.accept) return stamp.problem;
  *backwards = stamp.backwards;
  if (!stamp.problem.empty()) NODELET_WARN("dslam: %s", stamp.problem.c_str());
  const std::string colour_id = NormaliseFrameId(input.colour->header.frame_id);
  const std::string depth_id = NormaliseFrameId(input.depth->header.frame_id);
  if (colour_id != depth_id) {
    NODELET_WARN_THROTTLE(30.0,
                          "dslam: colour frame '%s' and depth frame '%s' differ: depth must be "
                          "registered to the colour camera (used as if it were)",
                          colour_id.c_str(), depth_id.c_str());
  }
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
    return e.what();
  }
  const std::string problem = frame->Check();
  if (!problem.empty()) {
    return problem + " (colour " + std::to_string(input.colour->width) + "x" +
           std::to_string(input.colour->height) + ", depth " + std::to_string(input.depth->width) +
           "x" + std::to_string(input.depth->height) + ")";
  }
  return "";
}

OdometryNodelet::PreFrameReset OdometryNodelet::ResetBeforeFrame(bool backwards) {
  const bool loaded_map = keyframe_maps_->HasLoadedMap();
  if (backwards && loaded_map) {
    reset_requested_.store(false);  // this reset serves a request as well
    slam_->Reset(ResetMode::kNewWorld);
    keyframe_maps_->AfterReset();
    return PreFrameReset::kBackwardsInLoadedMap;
  }
  if (!reset_requested_.exchange(false)) return PreFrameReset::kNone;
  slam_->Reset(ResetMode::kKeepPose);
  keyframe_maps_->AfterReset();
  NODELET_INFO(
      "dslam: reset by the reset service: %s",
      loaded_map ? "localising in the loaded keyframe map" : "re-initialising at the last pose");
  return PreFrameReset::kService;
}

void OdometryNodelet::RecordPose(const FrameResult& result, bool new_world) {
  const std::lock_guard<std::mutex> lock(trajectory_mutex_);
  if (new_world) {
    recorder_->StartSegment();
    segment_first_stamp_s_.reset();
  }
  if (!result.has_pose) return;
  recorder_->Add({result.stamp_s, result.T_world_camera});
  if (!segment_first_stamp_s_) segment_first_stamp_s_ = result.stamp_s;
}

void OdometryNodelet::Publish(const Input& input, const RgbdFrame& frame,
                              const FrameResult& result) {
  std_msgs::Header header = input.colour->header;
  header.frame_id =
      NormaliseFrameId(config_.camera_frame.empty() ? header.frame_id : config_.camera_frame);
  const Eigen::Isometry3d& T_base_camera = CameraMount(header.frame_id, header.stamp);
  const bool loops_changed = keyframe_map_publisher_->RefreshLoopStatus(result.keyframe);
  publisher_->SetLoopStatus(keyframe_map_publisher_->loop_status());
  const double latency_ms = (ros::WallTime::now() - input.received).toSec() * 1e3;
  publisher_->Publish(result, frame, header, T_base_camera, Counters(), latency_ms);
  const WorldDataFrame world = publisher_->WorldData(T_base_camera);
  if (map_publisher_) map_publisher_->SetWorldFrame(world.T_frame_world);
  if (grid_publisher_) grid_publisher_->SetWorldFrame(world.T_frame_world);
  std_msgs::Header world_header = header;
  world_header.frame_id = world.frame_id;
  objects_publisher_->Publish(frame, result, world_header, world.T_frame_world);
  keyframe_map_publisher_->Publish(result.keyframe || loops_changed, world_header,
                                   world.T_frame_world, T_base_camera);
}

FrameCounters OdometryNodelet::Counters() const {
  uint64_t errors = 0;
  if (slam_) errors += slam_->errors()->count();
  if (loop_closing_) errors += loop_closing_->errors()->count();
  if (objects_publisher_) errors += objects_publisher_->errors().count();
  return {received_.load(), processed_.load(), slot_.dropped(), rejected_.load(),
          errors,           map_lock_max_ms_};
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

}  // namespace ros_layer
}  // namespace dslam
