#pragma once
// What a timer-driven publisher of the static map (static_map, grid) last sent, so that it sends
// again only when the map or its transform changed: the transform of the tracker's world into the
// published frame, set by the worker with each frame, and the map revision and transform of the
// last message. Thread-safe (one mutex, never held while calling out).

#include <cstdint>
#include <mutex>
#include <optional>

#include <Eigen/Geometry>

namespace dslam {
namespace ros_layer {

/// See above.
class MapRevisionGate {
 public:
  /// WorldDataFrame::T_frame_world [m] of the newest frame (the worker's call).
  void SetWorldFrame(const Eigen::Isometry3d& T_frame_world) {
    const std::lock_guard<std::mutex> lock(mutex_);
    T_frame_world_ = T_frame_world;
  }

  /// The newest T_frame_world, when the worker has set one.
  std::optional<Eigen::Isometry3d> WorldFrame() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return T_frame_world_;
  }

  /// The transform to publish the map of `revision` with, recorded as published; nothing when
  /// no transform is known yet or neither the revision nor the transform changed since the last
  /// message (in odom_frame, without publish_map_tf, the transform changes with corrections).
  std::optional<Eigen::Isometry3d> TakeChange(uint64_t revision) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!T_frame_world_ || (published_revision_ == revision &&
                            published_T_frame_world_.matrix() == T_frame_world_->matrix())) {
      return std::nullopt;
    }
    published_revision_ = revision;
    published_T_frame_world_ = *T_frame_world_;
    return T_frame_world_;
  }

 private:
  mutable std::mutex mutex_;                        ///< guards the three members below
  std::optional<Eigen::Isometry3d> T_frame_world_;  ///< set by the worker
  std::optional<uint64_t> published_revision_;      ///< of the last message sent
  Eigen::Isometry3d published_T_frame_world_ = Eigen::Isometry3d::Identity();  ///< of the same
};

}  // namespace ros_layer
}  // namespace dslam
