#pragma once
// Every frame's pose re-expressed on its reference keyframe after the back end has refined the
// keyframes (as ORB-SLAM2's trajectory file): T_world_camera = T_world_keyframe (latest) *
// T_keyframe_camera (fixed when the frame was tracked). The causal trajectory (each pose as
// estimated at its frame) is what FrameResult reports; this one is for offline evaluation and
// the node's save_refined_trajectory.
//
// After a loop correction (FollowCorrection) a keyframe erased from the map moves with the
// nearest older keyframe the correction moved, as the static map's fused keyframes do.
//
// Memory and copies over hours: a frame costs 40 bytes, a keyframe erased from the map 64
// (T_keyframe_camera in single precision: below 1e-7 m and 1e-7 rad for keyframe offsets under a
// metre, under the 1e-6 m the trajectory files print). Full blocks of frames never change: they
// go to an unnamed temporary file (std::tmpfile, under $TMPDIR or /tmp, gone when the process
// ends), so memory holds one open block of frames whatever the run's length (4.3 MB an hour at
// 30 Hz otherwise); where no such file can be made or written, the blocks stay in memory. The
// poses of keyframes erased from the map are kept in full blocks in memory (a loop correction
// writes them again). Snapshots share both, so Take() copies a few pointers, the open blocks and
// the poses of the keyframes still in the map: Slam takes it under its map lock and computes the
// poses, reading the file, after releasing it.

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "dslam/core/trajectory.h"
#include "dslam/tracking/map.h"

namespace dslam {

/// Records frames relative to keyframes and follows the keyframes' refined poses.
class RefinedTrajectory {
 public:
  /// A frame as recorded: its stamp [s], its reference keyframe and T_keyframe_camera [m]
  /// (translation, then rotation as quaternion x, y, z, w).
  struct Frame {
    double stamp_s;
    int32_t keyframe_id;
    float t_keyframe_camera[3];
    float q_keyframe_camera[4];
  };
  /// A keyframe erased from the map at its last pose T_world_keyframe [m] (translation, then
  /// rotation as quaternion x, y, z, w): 64 bytes where an id and an Isometry3d take 136.
  struct ErasedKeyFrame {
    int32_t id;
    double q_world_keyframe[4];
    double t_world_keyframe[3];
  };
  class BlockFile;  ///< full blocks of frames in a temporary file (refined_trajectory.cpp)

  /// What Poses needs, copied cheaply (top of this file).
  struct Snapshot {
    std::shared_ptr<const BlockFile> file;  ///< the first `filed_blocks` blocks (null: none)
    size_t filed_blocks = 0;
    /// Full blocks after the filed ones (kept in memory), then the open block.
    std::vector<std::shared_ptr<const std::vector<Frame>>> frames;
    /// Keyframes erased from the map, at their last pose (full blocks, then the open one).
    std::vector<std::shared_ptr<const std::vector<ErasedKeyFrame>>> erased;
    std::unordered_map<int, Eigen::Isometry3d> live;  ///< keyframes in the map [m]
    /// The frames with their refined poses, in the order they were added.
    Trajectory Poses() const;
  };

  /// Blocks of frames go to a temporary file when one can be made (top of this file).
  RefinedTrajectory();
  ~RefinedTrajectory();
  RefinedTrajectory(const RefinedTrajectory&) = delete;
  RefinedTrajectory& operator=(const RefinedTrajectory&) = delete;

  /// Records a tracked frame at `stamp_s` [s] with pose T_world_camera [m], anchored on the
  /// newest keyframe of `map` (the frame's own keyframe when it became one). Ignored when the map
  /// has no keyframe.
  void AddFrame(double stamp_s, const Eigen::Isometry3d& T_world_camera, const Map& map);

  /// Takes the current poses of the keyframes in `map`, window and archive (call after the back
  /// end or a re-anchoring changed them). Keyframes erased from the map keep their last pose.
  void UpdateKeyFrames(const Map& map);

  /// UpdateKeyFrames after a loop correction moved the keyframes of `map`: the keyframes erased
  /// from the map before it move too, each as KeyFrameMotion says (with the nearest older keyframe
  /// the correction moved), and so do the frames anchored on them. O(erased keyframes): the
  /// erased blocks are written anew (snapshots keep the blocks they hold).
  void FollowCorrection(const Map& map);

  /// The state Poses() reads; O(keyframes in the map + one block), not O(frames).
  Snapshot Take() const;
  /// Take().Poses().
  Trajectory Poses() const { return Take().Poses(); }
  /// [-] frames recorded.
  size_t size() const {
    return (filed_blocks_ + frame_blocks_.size()) * kBlock + open_frames_.size();
  }
  /// Whether full blocks of frames go to the temporary file (false: none could be made, or a
  /// write failed and the later blocks stay in memory).
  bool FramesFiled() const { return file_ != nullptr && frame_blocks_.empty(); }

  static constexpr size_t kBlock = 4096;  ///< entries per full block

 private:
  /// Moves keyframes of live_ that `map` no longer has to the erased blocks.
  void RetireErased(const Map& map);

  /// Moves the full open block of frames to the file, or to frame_blocks_.
  void CloseFrameBlock();

  std::shared_ptr<BlockFile> file_;  ///< null: blocks stay in memory
  /// Full blocks in file_; the later ones in frame_blocks_ (after a failed write).
  size_t filed_blocks_ = 0;
  std::vector<std::shared_ptr<const std::vector<Frame>>> frame_blocks_;  ///< each kBlock frames
  std::vector<Frame> open_frames_;
  std::vector<std::shared_ptr<const std::vector<ErasedKeyFrame>>> erased_;
  std::vector<ErasedKeyFrame> open_erased_;
  std::unordered_map<int, Eigen::Isometry3d> live_;
  size_t live_limit_ = 64;  ///< RetireErased runs when live_ grows past it
};

}  // namespace dslam
