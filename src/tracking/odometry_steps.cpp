// The steps of Odometry::ProcessFrame (odometry.cpp), one function each.
#include <algorithm>
#include <string>

#include "dslam/core/side_by_side.h"
#include "dslam/tracking/id_set.h"
#include "dslam/tracking/map_point_creation.h"
#include "dslam/tracking/odometry.h"

namespace dslam {
namespace {

// [m] The near plane of the local-map search: map points nearer than this along the optical axis
// (so also points behind the camera) are not projected. Keeps projections off z = 0; below every
// sensor's depth range (depth_noise.min_depth_m 0.3 m by default).
constexpr double kSearchMinDepthM = 0.1;

// Sightings (frames a point projected into the image) before map culling checks a point's
// found/visible ratio (tracking.cull_min_found_ratio).
constexpr int kCullMinVisible = 8;

}  // namespace

void Odometry::MatchLocalMapPoints(Current* current, const Eigen::Isometry3d& T_camera_world,
                                   bool wide) {
  const TrackingConfig& cfg = config_.tracking;
  const PinholeCamera& camera = *current->frame->camera;
  current->local_points = map_.LocalPoints(last_tracked_, StaticSeenSinceFrame());
  const std::vector<PointId>& local = current->local_points;
  const double radius = wide ? cfg.wide_search_radius_px : cfg.search_radius_px;
  current->matches = MatchLocalMap(&map_, local, current->features, camera, T_camera_world,
                                   SearchWithin(radius, true), &current->feature_taken);
  if (static_cast<int>(current->matches.size()) >= cfg.min_matches || wide) return;
  // Too few: the prediction was off (sudden motion). Search the rest with a wide radius.
  MatchUnmatchedLocalPoints(current, T_camera_world, cfg.wide_search_radius_px);
}

void Odometry::MatchUnmatchedLocalPoints(Current* current, const Eigen::Isometry3d& T_camera_world,
                                         double radius_px) {
  const std::vector<PointMatch> more = ClaimLocalMapMatches(
      ProjectUnmatchedLocalPoints(*current, T_camera_world, SearchWithin(radius_px, false)),
      current->features, &current->feature_taken);
  current->matches.insert(current->matches.end(), more.begin(), more.end());
}

ProjectedLocalMap Odometry::ProjectUnmatchedLocalPoints(const Current& current,
                                                        const Eigen::Isometry3d& T_camera_world,
                                                        const LocalMapSearch& search) const {
  IdSet matched(current.matches.size());
  for (const PointMatch& m : current.matches) matched.Insert(m.id);
  std::vector<PointId> rest;
  for (PointId id : current.local_points) {
    if (!matched.Contains(id)) rest.push_back(id);
  }
  return ProjectLocalMap(map_, rest, current.features, *current.frame->camera, T_camera_world,
                         search);
}

LocalMapSearch Odometry::SearchWithin(double radius_px, bool count_visible) const {
  LocalMapSearch search;
  search.radius_px = radius_px;
  search.min_depth_m = kSearchMinDepthM;
  search.count_visible = count_visible;
  if (config_.tracking.follow_last_measurement) search.last_frame = &previous_;
  return search;
}

bool Odometry::EnoughInliers(const PoseResult& pose) const {
  return pose.success && pose.num_inliers >= config_.tracking.min_static_inliers;
}

PoseResult Odometry::SolvePoseFromStaticPoints(const Current& current,
                                               const Eigen::Isometry3d& T_camera_world) const {
  const PinholeCamera& camera = *current.frame->camera;
  PoseResult verified =
      EstimatePoseFromMatches(map_, current.matches, current.features, camera, T_camera_world,
                              PointSelection::kVerified, current.excluded, config_);
  if (EnoughInliers(verified)) return verified;
  // Too few verified points (new scene parts): candidates help until they are verified.
  return EstimatePoseFromMatches(map_, current.matches, current.features, camera, T_camera_world,
                                 PointSelection::kMarked, current.excluded, config_);
}

PoseResult Odometry::RobustPose(const Current& current, PointSelection voters,
                                uint32_t ransac_seed) const {
  return EstimateRobustPoseFromMatches(map_, current.matches, current.features,
                                       *current.frame->camera, voters, config_, ransac_seed);
}

bool Odometry::SolvePose(Current* current, const Eigen::Isometry3d& T_camera_world_guess,
                         uint32_t ransac_seed) {
  current->pose = SolvePoseFromStaticPoints(*current, T_camera_world_guess);
  if (!EnoughInliers(current->pose)) {
    // Too few inliers from the static points at the predicted pose (fast motion, or people fill
    // the view): a RANSAC pose needs no prediction. The marked matches vote first (a crowd
    // filling the view cannot win), then all of them.
    current->pose = RobustPose(*current, PointSelection::kMarked, ransac_seed);
    if (!EnoughInliers(current->pose)) {
      current->pose = RobustPose(*current, PointSelection::kAll, ransac_seed);
    }
    if (!EnoughInliers(current->pose)) return false;
    current->from_robust_pose = true;
  }
  current->T_camera_world = current->pose.T_camera_world;
  return true;
}

std::vector<const FrameMeasurements*> Odometry::FrontEndReferenceFrames() const {
  const TrackingConfig& cfg = config_.tracking;
  std::vector<const FrameMeasurements*> frames;
  if (cfg.front_end_reference != "previous") {
    // Keyframes at least front_end_min_age_frames old (a short baseline hides walking people),
    // spread evenly from the oldest of the newest keyframes (longest baseline) to the newest
    // eligible one.
    const auto& keyframes = map_.keyframes();
    const int first = static_cast<int>(map_.first_recent_keyframe());
    const int now = frame_index_ - 1;
    int n = static_cast<int>(keyframes.size()) - first;
    while (n > 1 && now - keyframes[first + n - 1].frame_index < cfg.front_end_min_age_frames) --n;
    const int k = std::min(n, cfg.front_end_keyframes);
    for (int i = 0; i < k; ++i) {
      const int index = first + (k == 1 ? 0 : i * (n - 1) / (k - 1));
      frames.push_back(&keyframes[index].measurements);
    }
  }
  if (cfg.front_end_reference != "keyframes" && !previous_.by_point.empty()) {
    frames.push_back(&previous_);
  }
  return frames;
}

void Odometry::RunFrontEndStaticPoints(Current* current, FrameResult* result) {
  // The search needs the initial pose and the matches so far, not the labels; the labelling
  // writes only points' labels, which the search does not read: the points (with their radii
  // from the labels before this frame's) are projected before both start. The search works on
  // a copy of feature_taken, which the labelling does not read either.
  const TrackingConfig& cfg = config_.tracking;
  const ProjectedLocalMap rest = ProjectUnmatchedLocalPoints(
      *current, current->T_camera_world, SearchWithin(cfg.search_radius_px, false));
  std::vector<PointMatch> more;
  std::vector<bool> taken = current->feature_taken;
  RunSideBySide([&] { more = ClaimLocalMapMatches(rest, current->features, &taken); },
                [&] { DetermineFrontEndLabels(current, result); });
  current->feature_taken = std::move(taken);
  current->matches.insert(current->matches.end(), more.begin(), more.end());
  current->excluded.resize(current->matches.size(), false);  // new matches: not yet judged
}

void Odometry::DetermineFrontEndLabels(Current* current, FrameResult* result) {
  if (!config_.static_points.enabled) return;  // the static-world baseline
  current->static_points = DetermineStaticPointsFrontEnd(
      map_, current->matches, current->features, current->T_camera_world, FrontEndReferenceFrames(),
      config_.static_points, std::move(current->graph));
  const TrackingConfig& cfg = config_.tracking;
  const LabelRules rules{cfg.isolated_frames_to_unmark, cfg.verify_frames, cfg.remark_frames};
  current->excluded = ApplyStaticLabels(current->static_points, current->matches, rules,
                                        result->frame_index, &map_);
  const StaticPointsStats& stats = current->static_points.result.stats;
  result->counts.graph_points = stats.points;
  result->counts.graph_edges = stats.edges;
  result->counts.culled_edges = stats.culled_edges;
}

bool Odometry::RefinePoseWithStaticPoints(Current* current, FrameResult* result) {
  if (!SolvePose(current, current->T_camera_world,
                 static_cast<uint32_t>(result->frame_index) + 1u)) {
    return false;
  }
  const bool relocalised = current->relocalisation_inliers > 0;
  result->state = current->from_robust_pose || relocalised ? TrackingState::kRecovered
                                                           : TrackingState::kTracking;
  if (relocalised) {
    result->message = "relocalised by descriptors against the window's keyframes (" +
                      std::to_string(current->relocalisation_inliers) + " of " +
                      std::to_string(current->relocalisation_matches) + " matches agree)";
  }
  return true;
}

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

bool Odometry::DrovePose(const Current& current, size_t m) {
  return current.pose.inliers[m] && (current.excluded.empty() || !current.excluded[m]);
}

void Odometry::FuseStaticPoints(const Current& current) {
  const Eigen::Isometry3d T_world_camera = current.T_camera_world.inverse();
  for (size_t m = 0; m < current.matches.size(); ++m) {
    MapPoint* point = map_.FindWritable(current.matches[m].id);  // frozen points stay
    const auto& measurement = current.features.features[current.matches[m].feature].measurement;
    if (point == nullptr || !measurement || !point->IsVerifiedStatic()) continue;
    if (!DrovePose(current, m)) continue;
    // Information-weighted mean of the map position and this keyframe's measurement.
    const Eigen::Matrix3d info_map = point->cov_world.inverse();
    const PointMeasurement in_world = Transformed(*measurement, T_world_camera);
    const Eigen::Matrix3d info_obs = in_world.covariance.inverse();
    const Eigen::Matrix3d cov = (info_map + info_obs).inverse();
    point->p_world = cov * (info_map * point->p_world + info_obs * in_world.y_camera);
    point->cov_world = cov;
  }
}

int Odometry::MakeKeyFrame(const Current& current) {
  const TrackingConfig& cfg = config_.tracking;
  if (cfg.fuse_static_points) FuseStaticPoints(current);
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
  map_.Cull(map_.keyframes()[map_.first_recent_keyframe()].frame_index, cfg.cull_min_found_ratio,
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
  const KeyFrame& newest = map_.keyframes().back();
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
