#pragma once
// The hook through which Slam hands its keyframes to consumers above the back end (the static
// map of part `mapping`) without depending on them: an observer interface declared here and
// implemented above. Slam calls it with the new keyframes' images and point labels and the
// window's current (refined) poses, never while it holds its map lock, from one thread at a time
// (threaded mode: Slam's back-end thread after local mapping; synchronous mode: the caller of
// ProcessFrame and Reset). See slam.h, "Locking policy".

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "dslam/core/rgbd_frame.h"
#include "dslam/tracking/frame_result.h"
#include "dslam/tracking/odometry.h"

namespace dslam {

/// One keyframe as the odometry made it, for consumers of its images.
struct KeyFrameRecord {
  int id = -1;  ///< KeyFrame::id (unique within a Slam, also across resets)
  /// The frame it was made from: a shallow copy (cv::Mat shares the caller's pixels, which the
  /// caller must not overwrite after ProcessFrame returns).
  RgbdFrame frame;
  /// [m] optical frame -> world (odometry) frame, as the front end estimated it at this frame.
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  /// The matched map points with their labels at the end of the frame (FrameResult::points):
  /// unmarked ones (is_static false) were seen moving.
  std::vector<ObservedPoint> points;
  /// From a loaded keyframe map (Slam::StartInMap), delivered after its reset: made by an
  /// earlier run, not by this one's odometry (loop closing enters it in its place database
  /// without searching a loop for it).
  bool loaded = false;
  /// Made while the odometry localises only in a loaded map (LoadedMapUse::kLocalisationOnly):
  /// the map erases it once it leaves the window (Map::Freeze), and loop closing neither enters it
  /// in its place database nor searches a loop for it.
  bool temporary = false;
};

/// Pose of a keyframe of the current window.
struct KeyFramePose {
  int id = -1;                                                       ///< KeyFrame::id
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();  ///< [m] optical -> world
};

/// Receives Slam's keyframes in the order they were made, and its resets in order with them.
/// Calls never overlap; an exception thrown by a call is reported to Slam::errors() under name()
/// and the other observers still get the event.
class KeyFrameObserver {
 public:
  virtual ~KeyFrameObserver() = default;

  /// `added`: keyframes made since the previous call, oldest first (none when only the poses
  /// changed). `window`: every keyframe in Slam's window now, oldest first, with its current
  /// pose (refined by local mapping when the back end is on); a keyframe absent from it left the
  /// window: local mapping no longer moves it, a loop correction still may (OnCorrection).
  virtual void OnKeyFrames(const std::vector<KeyFrameRecord>& added,
                           const std::vector<KeyFramePose>& window) = 0;

  /// The odometry was reset (Slam::Reset, or time went backwards: kNewWorld). Keyframes after it
  /// belong to the new run; with kNewWorld to a new world frame.
  virtual void OnReset(ResetMode mode) = 0;
  /// The keyframe map was corrected (Slam::CorrectKeyFrames: a loop): `keyframes` is every
  /// keyframe of the map, window and archive, oldest first, at its corrected pose. Delivered after
  /// the keyframes of the same delivery (those made before the correction are in the list at
  /// their corrected poses); a reset after it drops it. The default ignores it.
  virtual void OnCorrection(const std::vector<KeyFramePose>& keyframes) {}
  /// Slam is being destroyed: called once by ~Slam after its back-end thread ended, on the
  /// destroying thread. An observer that calls Slam from a thread of its own stops doing so
  /// before it returns. It must not throw (a destructor calls it). The default does nothing.
  virtual void OnStop() {}
  /// How Slam::errors() names this observer's errors.
  virtual std::string name() const { return "keyframe observer"; }
};

}  // namespace dslam
