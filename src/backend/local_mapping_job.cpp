#include "dslam/backend/local_mapping_job.h"

#include <unordered_set>

#include "dslam/backend/local_bundle_adjustment.h"
#include "dslam/backend/window_static_points.h"
#include "dslam/core/geometry.h"

namespace dslam {

LocalMappingJob::LocalMappingJob(const Map& map, uint64_t generation)
    : window_(map.WindowCopy()),
      generation_(generation),
      first_new_point_id_(map.next_point_id()),
      map_corrections_(map.corrections()) {
  if (!window_.window().empty()) {
    newest_keyframe_id_ = window_.window().back().id;
    T_world_newest_copied_ = window_.window().back().T_world_camera;
  }
  for (const KeyFrame& keyframe : window_.window()) {
    for (const auto& entry : keyframe.measurements.by_point) {
      const MapPoint* point = window_.Find(entry.first);
      if (point != nullptr)
        before_.emplace(entry.first, PointBefore{point->p_world, point->marked});
    }
  }
}

void LocalMappingJob::Run(const Config& config) {
  unmark_min_dynamic_frames_ = config.tracking.remark_frames;
  // Algorithm 1 over the window first: local BA then uses only the points that stayed marked.
  if (config.static_points.enabled) status_.spd = DetermineStaticPointsInWindow(config, &window_);
  status_.ba = LocalBundleAdjustment(config, &window_);
}

void LocalMappingJob::Apply(Map* map) const {
  if (map->corrections() != map_corrections_) {  // the copy's world is not the map's any more
    ApplyToPoints(map, /*move_points=*/false);
    return;
  }
  if (moved_keyframes()) {
    for (const KeyFrame& refined : window_.window()) {
      KeyFrame* live = map->FindKeyFrame(refined.id);
      if (live == nullptr || map->IsFrozenKeyFrame(refined.id)) continue;
      live->T_world_camera = refined.T_world_camera;
      live->measurements.T_camera_world = refined.measurements.T_camera_world;
    }
    MoveWhatWasMadeSince(map);
  }
  ApplyToPoints(map, /*move_points=*/true);
}

void LocalMappingJob::ApplyToPoints(Map* map, bool move_points) const {
  for (const auto& [id, before] : before_) {
    const MapPoint* refined = window_.Find(id);
    MapPoint* live = map->FindWritable(id);  // frozen points stay as they are
    if (refined == nullptr || live == nullptr) continue;
    if (move_points && refined->p_world != before.p_world) {
      if (live->p_world == before.p_world) {
        live->p_world = refined->p_world;
      } else if (live->marked) {
        live->p_world += refined->p_world - before.p_world;
      }
    }
    if (before.marked && !refined->marked) live->Unmark(unmark_min_dynamic_frames_);
  }
}

Eigen::Isometry3d LocalMappingJob::correction() const {
  if (!moved_keyframes() || window_.window().empty()) return Eigen::Isometry3d::Identity();
  return window_.window().back().T_world_camera * T_world_newest_copied_.inverse();
}

void LocalMappingJob::MoveWhatWasMadeSince(Map* map) const {
  const Eigen::Isometry3d T_new_old = correction();
  std::unordered_set<PointId> moved;
  for (KeyFrame& keyframe : map->mutable_window()) {
    if (keyframe.id <= newest_keyframe_id_) continue;
    keyframe.T_world_camera = T_new_old * keyframe.T_world_camera;
    keyframe.measurements.T_camera_world = keyframe.T_world_camera.inverse();
    for (PointId id : keyframe.points) {
      MapPoint* point = map->Find(id);
      if (id < first_new_point_id_ || point == nullptr || !moved.insert(id).second) continue;
      point->p_world = T_new_old * point->p_world;
      point->cov_world = RotatedCovariance(T_new_old.linear(), point->cov_world);
    }
  }
}

}  // namespace dslam
