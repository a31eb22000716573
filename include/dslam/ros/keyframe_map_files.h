#pragma once
// The node's keyframe map files (issue 34): the map of ~keyframe_map loaded at start and started
// in at the first frame (its camera is known only then) and again after each reset, extended or,
// with ~localisation_only, left as loaded (LoadedMapUse); the service save_keyframe_map and the
// save on shutdown (~save_keyframe_map_on_exit), which with ~localisation_only write the loaded
// file unchanged; the keyframe images kept for saving (~keyframe_map_images). The file handling
// itself is map_file's (keyframe_map_session.h), shared with dslam_run_dataset.
//
// Threads: BeforeFrame, AfterFrame and AfterReset are called by the worker thread only; the
// service runs on a ROS callback thread and reads the map through Slam (its map lock) and the
// camera and the loaded file under this object's own mutex, never holding both.

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "dslam/SaveKeyFrameMap.h"
#include "dslam/backend/slam.h"
#include "dslam/map_file/keyframe_map_session.h"
#include "dslam/ros/node_config.h"

namespace dslam {
namespace ros_layer {

/// Loads, starts in and saves keyframe maps for the nodelet.
class KeyFrameMapFiles {
 public:
  /// Reads config.keyframe_map (a file that cannot be read is reported and left out: the node
  /// maps from scratch) and advertises save_keyframe_map on `nh`. `vocabulary` is the node's.
  /// Throws std::invalid_argument naming ~localisation_only when it is set without
  /// ~keyframe_map.
  KeyFrameMapFiles(ros::NodeHandle& nh, const NodeConfig& config,
                   std::shared_ptr<const Vocabulary> vocabulary);

  /// The image keeper when config.keyframe_map_images, for Slam's constructor.
  std::vector<std::shared_ptr<KeyFrameObserver>> Observers() const;
  /// The Slam to start in the loaded map and to save; it must outlive this object's use of it.
  void Attach(Slam* slam);

  /// Before Slam::ProcessFrame (worker thread): starts the Slam in the loaded map when due (the
  /// first frame, and the first after a reset), checked against `camera`, the frame's camera.
  void BeforeFrame(const std::shared_ptr<const PinholeCamera>& camera);
  /// After Slam::ProcessFrame (worker thread): warns when the odometry reset itself while the
  /// frame was localising in the loaded map (the localisation's timeout: mapping goes on from
  /// scratch). Time going backwards never reaches the odometry with a map loaded: the node resets
  /// before the frame and calls AfterReset.
  void AfterFrame(const FrameResult& result, bool was_localising);
  /// The reset service reset the odometry (worker thread): the next frame starts in the loaded
  /// map again.
  void AfterReset();
  /// Whether a reset restarts in the loaded map (a map was loaded and not refused); any thread.
  bool HasLoadedMap();
  /// Writes config.save_keyframe_map_on_exit when set (call before the Slam is destroyed),
  /// keeping a file already there as PATH.prev.
  void SaveOnExit();

 private:
  bool OnSave(dslam::SaveKeyFrameMap::Request& req, dslam::SaveKeyFrameMap::Response& res);
  /// Saves the map to `path` (the loaded file when the node localises only in it); returns the
  /// response's message, throws on failure.
  /// `previous`: PreviousFile::kKeep keeps a file already at `path` as `path` + ".prev".
  std::string Save(const std::string& path, int* keyframes, int* points,
                   PreviousFile previous = PreviousFile::kReplace);
  /// " (~localisation_only has no effect)" when it is set, else "": for a refused map's error.
  const char* NoEffect() const;

  const NodeConfig config_;
  std::shared_ptr<const Vocabulary> vocabulary_;
  std::shared_ptr<KeyFrameImageKeeper> keeper_;  ///< null unless keyframe_map_images
  /// ~keyframe_map, never changed after loading; null: none, or refused. Set by the
  /// constructor, reset by the worker thread under mutex_, read by the service under mutex_.
  std::shared_ptr<const KeyFrameMapFile> loaded_;
  Slam* slam_ = nullptr;
  bool start_due_ = false;  ///< worker thread only
  ros::ServiceServer save_srv_;
  std::mutex mutex_;                             ///< guards camera_ and loaded_'s changes
  std::shared_ptr<const PinholeCamera> camera_;  ///< of the latest frame
};

}  // namespace ros_layer
}  // namespace dslam
