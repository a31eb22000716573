// The tracking steps of Odometry::ProcessFrame (odometry.cpp), one function each: local-map
// matching, the pose, front-end static point determination. The map-management steps are in
// odometry_keyframes.cpp.
#include <algorithm>
#include <string>

#include "dslam/core/side_by_side.h"
#include "dslam/tracking/id_set.h"
#include "dslam/tracking/odometry.h"

namespace dslam {
namespace {

// [m] The near plane of the local-map search: map points nearer than this along the optical axis
// (so also points behind the camera) are not projected. Keeps projections off z = 0; below every
// sensor's depth range (depth_noise.min_depth_m 0.3 m by default).
constexpr double kSearchMinDepthM = 0.1;

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
  // Keyframes at least front_end_min_age_frames old (a short baseline hides walking people),
  // spread evenly from the oldest of the newest keyframes (longest baseline) to the newest
  // eligible one.
  std::vector<const FrameMeasurements*> frames;
  const auto& keyframes = map_.window();
  const int first = static_cast<int>(map_.first_recent_keyframe());
  const int now = frame_index_ - 1;
  int n = static_cast<int>(keyframes.size()) - first;
  while (n > 1 && now - keyframes[first + n - 1].frame_index < cfg.front_end_min_age_frames) --n;
  const int k = std::min(n, cfg.front_end_keyframes);
  for (int i = 0; i < k; ++i) {
    const int index = first + (k == 1 ? 0 : i * (n - 1) / (k - 1));
    frames.push_back(&keyframes[index].measurements);
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

}  // namespace dslam
