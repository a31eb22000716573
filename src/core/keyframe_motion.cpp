#include "dslam/core/keyframe_motion.h"

namespace dslam {

void KeyFrameMotion::Add(int id, const Eigen::Isometry3d& T_world_camera_new,
                         const Eigen::Isometry3d& T_world_camera_old) {
  T_new_old_[id] = T_world_camera_new * T_world_camera_old.inverse();
}

Eigen::Isometry3d KeyFrameMotion::For(int id) const {
  if (T_new_old_.empty()) return Eigen::Isometry3d::Identity();
  auto nearest = T_new_old_.upper_bound(id);     // the first newer
  if (nearest != T_new_old_.begin()) --nearest;  // the nearest older (or itself)
  return nearest->second;
}

}  // namespace dslam
