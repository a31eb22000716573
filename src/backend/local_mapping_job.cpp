#include "dslam/backend/local_mapping_job.h"

#include "dslam/backend/local_bundle_adjustment.h"
#include "dslam/backend/window_static_points.h"

namespace dslam {

LocalMappingJob::LocalMappingJob(const Map& map, uint64_t generation)
    : window_(map.WindowCopy()), generation_(generation) {
  if (!window_.keyframes().empty()) newest_keyframe_id_ = window_.keyframes().back().id;
  for (const KeyFrame& keyframe : window_.keyframes()) {
    for (const auto& entry : keyframe.measurements.by_point) {
      const MapPoint* point = window_.Find(entry.first);
      if (point != nullptr)
        before_.emplace(entry.first, PointBefore{point->p_world, point->marked});
    }
  }
}

void LocalMappingJob::Run(const Config& config) {
  // Algorithm 1 over the window first: local BA then uses only the points that stayed marked.
  if (config.static_points.enabled) {
    const WindowStaticPointsStats spd = DetermineStaticPointsInWindow(config, &window_);
    status_.spd_ran = spd.ran;
    status_.spd_keyframes = spd.keyframes;
    status_.spd_points = spd.points;
    status_.spd_edges = spd.edges;
    status_.spd_culled_edges = spd.culled_edges;
    status_.spd_unmarked = spd.unmarked;
    status_.spd_graph_ms = spd.graph_ms;
    status_.spd_culling_ms = spd.culling_ms;
    status_.spd_components_ms = spd.components_ms;
    status_.spd_ms = spd.total_ms;
  }
  const LocalBaStats ba = LocalBundleAdjustment(config, &window_);
  status_.ran = ba.ran;
  status_.ba_keyframes = ba.keyframes;
  status_.ba_points = ba.points;
  status_.ba_measurements = ba.measurements;
  status_.ba_outliers = ba.outliers;
  status_.ba_iterations = ba.iterations;
  status_.ba_rejected = ba.rejected;
  status_.ba_ms = ba.time_ms;
}

void LocalMappingJob::Apply(Map* map) const {
  if (moved_keyframes()) {
    for (const KeyFrame& refined : window_.keyframes()) {
      KeyFrame* live = map->FindKeyFrame(refined.id);
      if (live == nullptr) continue;
      live->T_world_camera = refined.T_world_camera;
      live->measurements.T_camera_world = refined.measurements.T_camera_world;
    }
  }
  for (const auto& [id, before] : before_) {
    const MapPoint* refined = window_.Find(id);
    MapPoint* live = map->Find(id);
    if (refined == nullptr || live == nullptr) continue;
    if (refined->p_world != before.p_world) live->p_world = refined->p_world;
    if (before.marked && !refined->marked) {  // unmarked by the window (Unmark's fields)
      live->marked = false;
      live->candidate = refined->candidate;
      live->static_streak = refined->static_streak;
      live->dynamic_frames = refined->dynamic_frames;
    }
  }
}

}  // namespace dslam
