#include "dslam/ros/keyframe_map_files.h"

#include <filesystem>
#include <stdexcept>

namespace dslam {
namespace ros_layer {

KeyFrameMapFiles::KeyFrameMapFiles(ros::NodeHandle& nh, const NodeConfig& config,
                                   std::shared_ptr<const Vocabulary> vocabulary)
    : config_(config), vocabulary_(std::move(vocabulary)) {
  if (config_.localisation_only && config_.keyframe_map.empty()) {
    throw std::invalid_argument(
        "~localisation_only is true but ~keyframe_map is empty: no map to localise in");
  }
  if (config_.keyframe_map_images) keeper_ = std::make_shared<KeyFrameImageKeeper>();
  if (!config_.keyframe_map.empty()) {
    try {
      loaded_ = std::make_shared<const KeyFrameMapFile>(LoadKeyFrameMap(config_.keyframe_map));
      start_due_ = true;
      const std::string warning = KeyFrameMapWarning(*loaded_);
      if (!warning.empty()) {
        ROS_WARN("dslam: keyframe map %s: %s", config_.keyframe_map.c_str(), warning.c_str());
      }
      ROS_INFO("dslam: keyframe map %s: %zu keyframes, %zu points; localising in it%s",
               config_.keyframe_map.c_str(), loaded_->contents.keyframes.size(),
               loaded_->contents.points.size(),
               config_.localisation_only ? " (localisation only: the map stays as loaded)" : "");
    } catch (const std::exception& e) {
      ROS_ERROR("dslam: keyframe map refused, mapping from scratch%s: %s", NoEffect(), e.what());
    }
  }
  save_srv_ = nh.advertiseService("save_keyframe_map", &KeyFrameMapFiles::OnSave, this);
}

std::vector<std::shared_ptr<KeyFrameObserver>> KeyFrameMapFiles::Observers() const {
  if (!keeper_) return {};
  return {keeper_};
}

void KeyFrameMapFiles::Attach(Slam* slam) {
  slam_ = slam;
  if (keeper_) keeper_->Attach(slam);
}

void KeyFrameMapFiles::BeforeFrame(const std::shared_ptr<const PinholeCamera>& camera) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    camera_ = camera;
  }
  if (!start_due_ || !loaded_ || slam_ == nullptr) return;
  start_due_ = false;
  const std::string why = StartInKeyFrameMap(
      *loaded_, camera, vocabulary_, config_.localise_timeout_s, slam_,
      config_.localisation_only ? LoadedMapUse::kLocalisationOnly : LoadedMapUse::kExtend);
  if (!why.empty()) {
    ROS_ERROR("dslam: keyframe map %s refused, mapping from scratch%s: %s",
              config_.keyframe_map.c_str(), NoEffect(), why.c_str());
    const std::lock_guard<std::mutex> lock(mutex_);
    loaded_.reset();  // it will not fit later either
  }
}

const char* KeyFrameMapFiles::NoEffect() const {
  return config_.localisation_only ? " (~localisation_only has no effect)" : "";
}

void KeyFrameMapFiles::AfterFrame(const FrameResult& result, bool was_localising) {
  // The odometry's own reset while localising in a loaded map is the localisation's timeout:
  // time going backwards is reset before the frame (OdometryNodelet::ResetBeforeFrame).
  if (result.reset && loaded_ && was_localising) {
    ROS_WARN("dslam: %s (keyframe map %s)", result.message.c_str(), config_.keyframe_map.c_str());
  }
}

void KeyFrameMapFiles::AfterReset() { start_due_ = loaded_ != nullptr; }

bool KeyFrameMapFiles::HasLoadedMap() {
  const std::lock_guard<std::mutex> lock(mutex_);
  return loaded_ != nullptr;
}

void KeyFrameMapFiles::SaveOnExit() {
  if (config_.save_keyframe_map_on_exit.empty()) return;
  try {
    int keyframes = 0, points = 0;
    // Over an existing file, that file is kept as PATH.prev.
    ROS_INFO(
        "dslam: %s",
        Save(config_.save_keyframe_map_on_exit, &keyframes, &points, PreviousFile::kKeep).c_str());
  } catch (const std::exception& e) {
    ROS_ERROR("dslam: keyframe map not saved on exit: %s", e.what());
  }
}

bool KeyFrameMapFiles::OnSave(dslam::SaveKeyFrameMap::Request& req,
                              dslam::SaveKeyFrameMap::Response& res) {
  try {
    res.message = Save(req.path, &res.keyframes, &res.points);
    res.success = true;
  } catch (const std::exception& e) {
    res.success = false;
    res.message = e.what();
  }
  return true;
}

std::string KeyFrameMapFiles::Save(const std::string& path, int* keyframes, int* points,
                                   PreviousFile previous) {
  std::shared_ptr<const PinholeCamera> camera;
  std::shared_ptr<const KeyFrameMapFile> loaded;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    camera = camera_;
    loaded = loaded_;
  }
  if (!camera || slam_ == nullptr) throw std::runtime_error("no frame yet: no camera to save");
  // Localisation only: the map the node runs in is the loaded one, written as it was loaded.
  const bool unchanged = config_.localisation_only && loaded != nullptr;
  // The map lock only while the map is copied; images and the file after it.
  const KeyFrameMapFile file =
      unchanged ? *loaded : KeyFrameMapOf(*slam_, *camera, vocabulary_->identity(), keeper_.get());
  SaveKeyFrameMap(path, file, previous);
  *keyframes = static_cast<int>(file.contents.keyframes.size());
  *points = static_cast<int>(file.contents.points.size());
  return std::string(unchanged ? "localisation only: the loaded map unchanged: " : "") + "wrote " +
         std::to_string(*keyframes) + " keyframes, " + std::to_string(*points) + " points (" +
         std::to_string(std::filesystem::file_size(path)) + " bytes) to " + path;
}

}  // namespace ros_layer
}  // namespace dslam
