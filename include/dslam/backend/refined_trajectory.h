#pragma once
// Every frame's pose re-expressed on its reference keyframe after the back end has refined the
// keyframes (as ORB-SLAM2's trajectory file): T_world_camera = T_world_keyframe (latest) *
// T_keyframe_camera (fixed when the frame was tracked). The causal trajectory (each pose as
// estimated at its frame) is what FrameResult reports; this one is for offline evaluation.

#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "dslam/core/trajectory.h"
#include "dslam/tracking/map.h"

namespace dslam {

/// Records frames relative to keyframes and follows the keyframes' refined poses.
class RefinedTrajectory {
 public:
  /// Records a tracked frame at `stamp_s` [s] with pose T_world_camera, anchored on the newest
  /// keyframe of `map` (the frame's own keyframe when it became one). Ignored when the map has
  /// no keyframe.
  void AddFrame(double stamp_s, const Eigen::Isometry3d& T_world_camera, const Map& map);

  /// Takes the current poses of the keyframes in `map`, window and archive (call after the back
  /// end or a re-anchoring changed them). Keyframes erased from the map keep their last pose.
  void UpdateKeyFrames(const Map& map);

  /// The recorded frames with their refined poses, in the order they were added.
  Trajectory Poses() const;

 private:
  struct Frame {
    double stamp_s;
    int keyframe_id;
    Eigen::Isometry3d T_keyframe_camera;
  };
  std::vector<Frame> frames_;
  std::unordered_map<int, Eigen::Isometry3d> T_world_keyframe_;
};

}  // namespace dslam
