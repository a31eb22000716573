#include "dslam/backend/refined_trajectory.h"

namespace dslam {
namespace {

/// Appends `entry` to `open`, moving `open` into `blocks` as a full block at `block` entries.
template <typename T, typename Blocks>
void Append(T entry, size_t block, std::vector<T>* open, Blocks* blocks) {
  open->push_back(std::move(entry));
  if (open->size() < block) return;
  blocks->push_back(std::make_shared<const std::vector<T>>(std::move(*open)));
  open->clear();
  open->reserve(block);
}

RefinedTrajectory::Frame Compact(double stamp_s, int keyframe_id,
                                 const Eigen::Isometry3d& T_keyframe_camera) {
  const Eigen::Vector3d& t = T_keyframe_camera.translation();
  const Eigen::Quaterniond q(T_keyframe_camera.rotation());
  return {stamp_s,
          keyframe_id,
          {static_cast<float>(t.x()), static_cast<float>(t.y()), static_cast<float>(t.z())},
          {static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z()),
           static_cast<float>(q.w())}};
}

Eigen::Isometry3d Expand(const RefinedTrajectory::Frame& frame) {
  const float* q = frame.q_keyframe_camera;
  const float* t = frame.t_keyframe_camera;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized().toRotationMatrix();
  T.translation() = Eigen::Vector3d(t[0], t[1], t[2]);
  return T;
}

RefinedTrajectory::ErasedKeyFrame CompactErased(int id, const Eigen::Isometry3d& T_world_keyframe) {
  const Eigen::Quaterniond q(T_world_keyframe.rotation());
  const Eigen::Vector3d& t = T_world_keyframe.translation();
  return {id, {q.x(), q.y(), q.z(), q.w()}, {t.x(), t.y(), t.z()}};
}

Eigen::Isometry3d ExpandErased(const RefinedTrajectory::ErasedKeyFrame& keyframe) {
  const double* q = keyframe.q_world_keyframe;
  const double* t = keyframe.t_world_keyframe;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized().toRotationMatrix();
  T.translation() = Eigen::Vector3d(t[0], t[1], t[2]);
  return T;
}

}  // namespace

void RefinedTrajectory::AddFrame(double stamp_s, const Eigen::Isometry3d& T_world_camera,
                                 const Map& map) {
  if (map.keyframes().empty()) return;
  const KeyFrame& reference = map.keyframes().back();
  live_[reference.id] = reference.T_world_camera;
  if (live_.size() > live_limit_) RetireErased(map);
  const Frame frame =
      Compact(stamp_s, reference.id, reference.T_world_camera.inverse() * T_world_camera);
  Append(frame, kBlock, &open_frames_, &frame_blocks_);
}

void RefinedTrajectory::UpdateKeyFrames(const Map& map) {
  for (const KeyFrame& keyframe : map.keyframes()) live_[keyframe.id] = keyframe.T_world_camera;
  for (const auto& [id, keyframe] : map.archived_keyframes()) {
    live_[id] = keyframe.T_world_camera;
  }
  RetireErased(map);
}

void RefinedTrajectory::RetireErased(const Map& map) {
  for (auto it = live_.begin(); it != live_.end();) {
    if (map.FindKeyFrame(it->first) != nullptr) {
      ++it;
      continue;
    }
    Append(CompactErased(it->first, it->second), kBlock, &open_erased_, &erased_);
    it = live_.erase(it);
  }
  live_limit_ = 2 * live_.size() + 64;
}

RefinedTrajectory::Snapshot RefinedTrajectory::Take() const {
  Snapshot snapshot;
  snapshot.frames = frame_blocks_;
  snapshot.frames.push_back(std::make_shared<const std::vector<Frame>>(open_frames_));
  snapshot.erased = erased_;
  snapshot.erased.push_back(std::make_shared<const std::vector<ErasedKeyFrame>>(open_erased_));
  snapshot.live = live_;
  return snapshot;
}

Trajectory RefinedTrajectory::Snapshot::Poses() const {
  std::unordered_map<int, Eigen::Isometry3d> T_world_keyframe = live;
  for (const auto& block : erased) {
    for (const ErasedKeyFrame& keyframe : *block) {  // live ones win
      if (T_world_keyframe.count(keyframe.id) == 0) {
        T_world_keyframe.emplace(keyframe.id, ExpandErased(keyframe));
      }
    }
  }
  Trajectory poses;
  for (const auto& block : frames) {
    for (const Frame& frame : *block) {
      poses.push_back({frame.stamp_s, T_world_keyframe.at(frame.keyframe_id) * Expand(frame)});
    }
  }
  return poses;
}

}  // namespace dslam
