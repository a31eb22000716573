// dslam_replay: publishes the frames of a TUM-layout folder (dslam_synth output, TUM RGB-D) at a
// fixed rate, looping over them, with stamps start + k / rate that keep increasing across loops
// (a long-run input for the odometry node; scripts/long_run.py). Every message is converted once at
// start; a publish only sets the header and serialises.
//   dslam_replay --dataset FOLDER [--rate 30] [--duration S] [--depth 32FC1|16UC1]
//                [--frame-id camera_rgb_optical_frame] [--wait-subscribers 30] [--max-frames N]
// Topics (relative, remappable): rgb/image (bgr8), depth/image (32FC1 metres or 16UC1
// millimetres), rgb/camera_info (plumb_bob). --duration 0 (the default) publishes until shut down.
#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <cv_bridge/cv_bridge.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/image_encodings.h>

#include "dslam/io/dataset_io.h"

namespace {

struct Options {
  std::string dataset;
  double rate_hz = 30.0;
  double duration_s = 0.0;  ///< [s] 0: until shut down
  std::string depth_encoding = "32FC1";
  std::string frame_id = "camera_rgb_optical_frame";
  double wait_subscribers_s = 30.0;  ///< [s] wait for a subscriber on every topic; 0: none
  int max_frames = 0;                ///< 0: every frame of the folder
};

/// One frame's images, converted once.
struct FrameMessages {
  sensor_msgs::Image colour;
  sensor_msgs::Image depth;
};

sensor_msgs::CameraInfo MakeCameraInfo(const dslam::PinholeCamera& camera,
                                       const std::string& frame_id) {
  sensor_msgs::CameraInfo info;
  info.header.frame_id = frame_id;
  info.width = camera.width();
  info.height = camera.height();
  info.distortion_model = "plumb_bob";
  const dslam::Distortion& d = camera.distortion();
  info.D = {d.k1, d.k2, d.p1, d.p2, d.k3};
  info.K = {camera.fx(), 0.0, camera.cx(), 0.0, camera.fy(), camera.cy(), 0.0, 0.0, 1.0};
  info.R = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  info.P = {camera.fx(), 0.0, camera.cx(), 0.0, 0.0, camera.fy(),
            camera.cy(), 0.0, 0.0,         0.0, 1.0, 0.0};
  return info;
}

/// Loads and converts every frame (up to options.max_frames); throws on unreadable files.
std::vector<FrameMessages> LoadFrames(const dslam::TumDataset& dataset, const Options& options) {
  namespace enc = sensor_msgs::image_encodings;
  size_t count = dataset.size();
  if (options.max_frames > 0) count = std::min(count, static_cast<size_t>(options.max_frames));
  std::vector<FrameMessages> frames(count);
  std_msgs::Header header;
  header.frame_id = options.frame_id;
  for (size_t i = 0; i < count; ++i) {
    const dslam::RgbdFrame frame = dataset.LoadFrame(i);
    cv_bridge::CvImage(header, enc::BGR8, frame.colour).toImageMsg(frames[i].colour);
    if (options.depth_encoding == "16UC1") {
      cv::Mat depth_mm;
      frame.depth_m.convertTo(depth_mm, CV_16UC1, 1000.0);  // rounds; 0 stays 0 (no depth)
      cv_bridge::CvImage(header, enc::TYPE_16UC1, depth_mm).toImageMsg(frames[i].depth);
    } else {
      cv_bridge::CvImage(header, enc::TYPE_32FC1, frame.depth_m).toImageMsg(frames[i].depth);
    }
  }
  return frames;
}

/// Waits until every publisher has a subscriber or `timeout_s` passed; false on timeout.
bool WaitForSubscribers(const std::vector<ros::Publisher*>& publishers, double timeout_s) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout_s);
  while (ros::ok() && ros::WallTime::now() < end) {
    bool all = true;
    for (const ros::Publisher* p : publishers) all = all && p->getNumSubscribers() > 0;
    if (all) return true;
    ros::WallDuration(0.05).sleep();
  }
  return false;
}

/// Counts of one replay.
struct ReplaySummary {
  uint64_t published = 0;
  uint64_t late = 0;         ///< frames published more than one period after their schedule
  double max_late_ms = 0.0;  ///< [ms] largest delay behind the schedule
  double seconds = 0.0;      ///< [s] wall time from the first to the last publish
};

/// Publishes frame k % N at wall time t0 + k / rate with stamp start + k / rate.
ReplaySummary Replay(std::vector<FrameMessages>* frames, sensor_msgs::CameraInfo* info,
                     const Options& options, ros::Publisher* colour_pub, ros::Publisher* depth_pub,
                     ros::Publisher* info_pub) {
  ReplaySummary summary;
  const double period_s = 1.0 / options.rate_hz;
  const ros::WallTime t0 = ros::WallTime::now();
  const ros::Time start = ros::Time::now();
  for (uint64_t k = 0; ros::ok(); ++k) {
    const double offset_s = static_cast<double>(k) * period_s;
    if (options.duration_s > 0.0 && offset_s >= options.duration_s) break;
    const ros::WallTime due = t0 + ros::WallDuration(offset_s);
    const ros::WallDuration wait = due - ros::WallTime::now();
    if (wait > ros::WallDuration(0.0)) wait.sleep();
    const double late_s = (ros::WallTime::now() - due).toSec();  // after the sleep
    if (late_s > period_s) ++summary.late;
    summary.max_late_ms = std::max(summary.max_late_ms, 1e3 * late_s);
    FrameMessages& frame = (*frames)[k % frames->size()];
    const ros::Time stamp = start + ros::Duration(offset_s);
    for (std_msgs::Header* h : {&frame.colour.header, &frame.depth.header, &info->header}) {
      h->stamp = stamp;
      h->seq = static_cast<uint32_t>(k);
    }
    // publish(const M&) serialises at once, so the next frame may change the headers.
    info_pub->publish(*info);
    depth_pub->publish(frame.depth);
    colour_pub->publish(frame.colour);
    ++summary.published;
    summary.seconds = (ros::WallTime::now() - t0).toSec();
  }
  return summary;
}

int Run(const Options& options) {
  const dslam::TumDataset dataset(options.dataset, "", 0.02);
  if (dataset.size() == 0) throw std::runtime_error("no colour/depth pairs in " + options.dataset);
  const ros::WallTime load_start = ros::WallTime::now();
  std::vector<FrameMessages> frames = LoadFrames(dataset, options);
  sensor_msgs::CameraInfo info = MakeCameraInfo(*dataset.camera_yaml().camera, options.frame_id);
  std::printf(
      "dslam_replay: %zu frames of %s converted in %.1f s; publishing at %.1f Hz for %.1f s "
      "(0: until shut down)\n",
      frames.size(), options.dataset.c_str(), (ros::WallTime::now() - load_start).toSec(),
      options.rate_hz, options.duration_s);
  std::fflush(stdout);
  ros::NodeHandle nh;
  ros::Publisher colour_pub = nh.advertise<sensor_msgs::Image>("rgb/image", 5);
  ros::Publisher depth_pub = nh.advertise<sensor_msgs::Image>("depth/image", 5);
  ros::Publisher info_pub = nh.advertise<sensor_msgs::CameraInfo>("rgb/camera_info", 5);
  if (options.wait_subscribers_s > 0.0 &&
      !WaitForSubscribers({&colour_pub, &depth_pub, &info_pub}, options.wait_subscribers_s)) {
    std::fprintf(stderr, "dslam_replay: no subscriber on every topic after %.1f s\n",
                 options.wait_subscribers_s);
    return 1;
  }
  const ReplaySummary s = Replay(&frames, &info, options, &colour_pub, &depth_pub, &info_pub);
  // roscpp sends on its own threads; messages still queued when the process exits are lost
  // (replay.test saw 59 of 60 camera_info messages arrive without this wait).
  ros::WallDuration(0.5).sleep();
  std::printf(
      "dslam_replay: published %lu frames (%.2f loops) in %.1f s (%.2f Hz); %lu more than one "
      "period late, max %.1f ms late\n",
      static_cast<unsigned long>(s.published), static_cast<double>(s.published) / frames.size(),
      s.seconds, s.seconds > 0.0 ? (s.published - 1) / s.seconds : 0.0,
      static_cast<unsigned long>(s.late), s.max_late_ms);
  return 0;
}

void PrintUsage() {
  std::fprintf(stderr,
               "usage: dslam_replay --dataset FOLDER [--rate HZ] [--duration S] [--depth "
               "32FC1|16UC1]\n"
               "                    [--frame-id ID] [--wait-subscribers S] [--max-frames N]\n");
}

/// Parses --key value pairs; false (after printing why) on an unknown key or bad value.
bool ParseOptions(const std::vector<std::string>& args, Options* o) {
  static const std::set<std::string> kKnown = {
      "dataset", "rate", "duration", "depth", "frame-id", "wait-subscribers", "max-frames"};
  std::map<std::string, std::string> values;
  for (size_t i = 0; i < args.size(); i += 2) {
    const std::string key = args[i].rfind("--", 0) == 0 ? args[i].substr(2) : "";
    if (!kKnown.count(key) || i + 1 >= args.size()) {
      std::fprintf(stderr, "dslam_replay: bad argument '%s'\n", args[i].c_str());
      return false;
    }
    values[key] = args[i + 1];
  }
  if (!values.count("dataset")) return false;
  o->dataset = values["dataset"];
  if (values.count("rate")) o->rate_hz = std::stod(values["rate"]);
  if (values.count("duration")) o->duration_s = std::stod(values["duration"]);
  if (values.count("depth")) o->depth_encoding = values["depth"];
  if (values.count("frame-id")) o->frame_id = values["frame-id"];
  if (values.count("wait-subscribers"))
    o->wait_subscribers_s = std::stod(values["wait-subscribers"]);
  if (values.count("max-frames")) o->max_frames = std::stoi(values["max-frames"]);
  if (o->rate_hz <= 0.0 || o->duration_s < 0.0 || o->max_frames < 0 ||
      (o->depth_encoding != "32FC1" && o->depth_encoding != "16UC1")) {
    std::fprintf(stderr,
                 "dslam_replay: --rate must be > 0, --duration and --max-frames >= 0, "
                 "--depth 32FC1 or 16UC1\n");
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "dslam_replay");  // removes the ROS remapping arguments from argv
  Options options;
  try {
    if (!ParseOptions(std::vector<std::string>(argv + 1, argv + argc), &options)) {
      PrintUsage();
      return 2;
    }
    return Run(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dslam_replay: %s\n", e.what());
    return 1;
  }
}
