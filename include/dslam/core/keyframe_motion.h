#pragma once
// How a correction (a closed loop) moved the world around each keyframe, for what follows keyframes
// the map no longer has: the static map's fused keyframes (StaticMapper::OnCorrection) and the
// erased keyframes of the refined trajectory (RefinedTrajectory::FollowCorrection).

#include <map>

#include <Eigen/Geometry>

namespace dslam {

/// T_new_old = [world_new <- world_old] of each keyframe a correction moved, by id, and one rule for
/// a keyframe it does not know (one the map erased before the correction): it moves with the
/// nearest older keyframe the correction moved, or with the nearest newer one when none is older.
class KeyFrameMotion {
 public:
  /// Records that keyframe `id` moved from T_world_camera_old to T_world_camera_new [m].
  void Add(int id, const Eigen::Isometry3d& T_world_camera_new,
           const Eigen::Isometry3d& T_world_camera_old);

  /// True when no keyframe was recorded.
  bool empty() const { return T_new_old_.empty(); }

  /// T_new_old for keyframe `id` by the rule above; the identity when nothing was recorded.
  Eigen::Isometry3d For(int id) const;

 private:
  std::map<int, Eigen::Isometry3d> T_new_old_;
};

}  // namespace dslam
