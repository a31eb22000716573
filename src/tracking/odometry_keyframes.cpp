// The map-management steps of Odometry::ProcessFrame (odometry.cpp, step 6; Sec. V-C), one
// function each: matched points updated, the keyframe decision, a keyframe with its new points,
// culling, and the frame's summary and views.
#include <algorithm>
#include <vector>

#include "dslam/tracking/map_point_creation.h"
#include "dslam/tracking/odometry.h"

namespace dslam {
namespace {

// Sightings (frames a point projected into the image) before map culling checks a point's
// found/visible ratio (tracking.cull_min_found_ratio).
constexpr int kCullMinVisible = 8;

}  // namespace

void Odometry::UpdateMatchedPoints(const Current& current) {
  const Eigen::Isometry3d T_world_camera = current.T_camera_world.inverse();
  previous_ = FrameMeasurements();
  previous_.T_camera_world = current.T_camera_world;
  last_tracked_.clear();
  for (const PointMatch& match : current.matches) {
    MapPoint* point = map_.Find(match.id);
    if (point == nullptr) continue;
    last_tracked_.push_back(match.id);
    const auto& measurement = current.features.features[match.feature].measurement;
    if (measurement) previous_.by_point.emplace(match.id, *measurement);
    if (map_.IsFrozenPoint(match.id)) continue;  // a frozen point stays as it was
    ++point->times_found;
    map_.MarkSeen(point, frame_index_ - 1);
    if (measurement && !point->marked) {
      // Unmarked points follow their object (Sec. V-C, update): matching keeps claiming its
      // features, so they do not come back as new marked points.
      const PointMeasurement in_world = Transformed(*measurement, T_world_camera);
      point->p_world = in_world.y_camera;
      point->cov_world = in_world.covariance;
    }
  }
}

KeyFrameMapLimits Odometry::MapLimits() const {
  const TrackingConfig& cfg = config_.tracking;
  return {cfg.window_keyframes, cfg.covisible_keyframes, cfg.max_keyframes};
}

int Odometry::StaticSeenSinceFrame() const {
  const int keep = config_.tracking.keep_static_frames;
  return keep > 0 ? std::max(0, frame_index_ - 1 - keep) : -1;
}

bool Odometry::NeedKeyFrame(int static_matches) const {
  const TrackingConfig& cfg = config_.tracking;
  const int since = frame_index_ - 1 - last_keyframe_frame_;
  if (since >= cfg.keyframe_max_interval) return true;
  if (since < cfg.keyframe_min_interval) return false;
  return static_matches < cfg.keyframe_min_static ||
         static_matches < cfg.keyframe_min_tracked_ratio * last_keyframe_static_;
}

int Odometry::MakeKeyFrame(const Current& current) {
  const TrackingConfig& cfg = config_.tracking;
  const int frame_index = frame_index_ - 1;
  const std::vector<int> dynamic = config_.static_points.enabled
                                       ? DynamicNeighbourhood(current.features, current.matches,
                                                              map_, cfg.dynamic_neighbour_radius_px)
                                       : std::vector<int>(current.features.features.size(), -1);
  CreationContext context{current.T_camera_world.inverse(), frame_index,
                          config_.static_points.enabled && cfg.verify_frames > 0};
  const std::vector<PointId> created =
      CreateMapPoints(current.features, current.feature_taken, dynamic, context, cfg, &map_);
  KeyFrame keyframe;
  keyframe.frame_index = frame_index;
  keyframe.stamp_s = current.frame->stamp_s;
  keyframe.T_world_camera = context.T_world_camera;
  keyframe.points = last_tracked_;
  keyframe.points.insert(keyframe.points.end(), created.begin(), created.end());
  keyframe.measurements = MeasurementsOf(current, created);
  keyframe.information = current.pose.information;
  keyframe.weak_since_previous = weak_since_keyframe_;
  map_.AddKeyFrame(std::move(keyframe), MapLimits());
  map_.Cull(map_.window()[map_.first_recent_keyframe()].frame_index, cfg.cull_min_found_ratio,
            kCullMinVisible, StaticSeenSinceFrame());
  last_keyframe_frame_ = frame_index;
  last_keyframe_static_ = current.pose.num_inliers;
  last_tracked_.insert(last_tracked_.end(), created.begin(), created.end());
  return static_cast<int>(created.size());
}

FrameMeasurements Odometry::MeasurementsOf(const Current& current,
                                           const std::vector<PointId>& created) const {
  FrameMeasurements out = previous_;  // the matched points' measurements of this frame
  out.T_camera_world = current.T_camera_world;
  for (PointId id : created) {
    const MapPoint* point = map_.Find(id);
    const auto& measurement = current.features.features[point->created_feature].measurement;
    out.by_point.emplace(id, *measurement);
  }
  return out;
}

void Odometry::Summarise(const Current& current, FrameResult* result) const {
  FrameCounts& counts = result->counts;
  counts.features = static_cast<int>(current.features.features.size());
  counts.features_with_depth = current.features.NumWithDepth();
  counts.tracked = static_cast<int>(current.matches.size());
  counts.pose_inliers = current.pose.num_inliers;
  counts.pose_observations = current.pose.num_observations;
  counts.pose_chi2_per_dof = current.pose.inlier_chi2_per_dof;
  counts.map_points = static_cast<int>(map_.size());
  for (const PointMatch& match : current.matches) {
    const MapPoint* point = map_.Find(match.id);
    if (point == nullptr) continue;
    (point->marked ? counts.static_points : counts.dynamic_points)++;
    if (point->IsCandidate()) ++counts.candidate_points;
  }
  AddViews(current, result);
}

void Odometry::AddViews(const Current& current, FrameResult* result) const {
  if (request_.points) {
    for (const PointMatch& match : current.matches) {
      const MapPoint* point = map_.Find(match.id);
      if (point == nullptr) continue;
      ObservedPoint observed;
      observed.id = match.id;
      observed.uv_raw = current.features.features[match.feature].uv_raw;
      observed.p_world = point->p_world;
      observed.is_static = point->marked;
      observed.is_candidate = point->IsCandidate();
      result->points.push_back(observed);
    }
  }
  if (!request_.edges) return;
  const StaticPointsResult& spd = current.static_points.result;
  for (size_t e = 0; e < spd.edges.size(); ++e) {
    const GraphEdge& edge = spd.edges[e];
    result->edges.push_back(
        {spd.points_world[edge.i], spd.points_world[edge.j], static_cast<bool>(spd.edge_kept[e])});
  }
}

void Odometry::RememberPoseOnNewestKeyFrame(int frame_index) {
  const KeyFrame& newest = map_.window().back();
  last_on_keyframe_.keyframe_id = newest.id;
  last_on_keyframe_.frame_index = frame_index;
  last_on_keyframe_.T_keyframe_camera = newest.T_world_camera.inverse() * motion_.last_pose();
}

void Odometry::AdoptNewestKeyFramePose() {
  const KeyFrame* keyframe = map_.FindKeyFrame(last_on_keyframe_.keyframe_id);
  if (keyframe == nullptr) return;
  if (keyframe->frame_index == last_on_keyframe_.frame_index) {  // made from the last frame
    motion_.CorrectLastPose(keyframe->T_world_camera);
    previous_.T_camera_world = keyframe->measurements.T_camera_world;
    return;
  }
  const Eigen::Isometry3d T_world_last =
      keyframe->T_world_camera * last_on_keyframe_.T_keyframe_camera;
  motion_.CorrectLastPose(T_world_last);
  previous_.T_camera_world = T_world_last.inverse();
}

}  // namespace dslam
