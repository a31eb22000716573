#include "dslam/tracking/odometry.h"

#include <stdexcept>
#include <string>

#include "dslam/core/side_by_side.h"
#include "dslam/core/stopwatch.h"
#include "dslam/tracking/map_point_creation.h"
#include "dslam/tracking/relocalisation.h"

namespace dslam {
namespace {

// Features with depth needed to (re-)initialise, as a multiple of tracking.min_static_inliers, so
// that initialisation follows that bound.
constexpr int kInitMinPointsFactor = 2;

}  // namespace

Odometry::Odometry(const Config& config) : config_(config) { config_.Validate(); }

void Odometry::Reset(ResetMode mode) {
  map_.Clear();
  if (mode == ResetMode::kNewWorld) {
    motion_.Reset();
    have_stamp_ = false;
  } else {
    motion_.ForgetVelocity();
  }
  previous_ = FrameMeasurements();
  last_on_keyframe_ = PoseOnKeyFrame();
  last_tracked_.clear();
  weak_episode_.End();
  weak_since_keyframe_ = false;
  places_.reset();
  localising_ = localise_started_ = localisation_only_ = false;
  initialised_ = false;
  frame_index_ = lost_frames_ = 0;
}

// The paper's front end (Sec. V), one frame.
FrameResult Odometry::ProcessFrame(const RgbdFrame& frame, const FrameRequest& request) {
  const std::string problem = frame.Check();
  if (!problem.empty()) throw std::invalid_argument("dslam: bad frame: " + problem);
  // 1. ORB features with depth and the 3x3 measurement covariance (Sec. V-A).
  const Stopwatch features;
  FrameFeatures extracted = ExtractFeatures(frame, config_.features, config_.depth_noise);
  return ProcessFrame(frame, std::move(extracted), features.ElapsedMs(), request);
}

FrameResult Odometry::ProcessFrame(const RgbdFrame& frame, FrameFeatures features,
                                   double features_ms, const FrameRequest& request) {
  const std::string problem = frame.Check();
  if (!problem.empty()) throw std::invalid_argument("dslam: bad frame: " + problem);
  request_ = request;
  Stopwatch total, stage;
  FrameResult result;
  result.reset = BeginFrame(frame, &result);
  Current current;
  current.frame = &frame;
  current.features = std::move(features);  // step 1, done by the caller
  current.feature_taken.assign(current.features.features.size(), false);
  result.times.features_ms = features_ms;
  stage.Restart();
  const std::string shortage = FeatureShortage(current.features);
  if (!shortage.empty()) return Lost(&current, std::move(result), shortage.c_str());
  // While starting in a loaded keyframe map (StartInMap): no pose until the frame is
  // relocalised in the map at a place that place recognition names.
  bool have_initial_pose = false;
  if (localising_) {
    have_initial_pose = LocaliseInLoadedMap(&current, result.frame_index);
    result.times.initial_pose_ms = stage.Restart();
    if (!have_initial_pose) return NotLocalised(&current, std::move(result));
  } else {
    // After lost_frames_before_reset lost frames the map is re-initialised (never in
    // localisation-only mode), unless this frame can still be relocalised in it (step 3).
    if (!initialised_ && !CanRelocalise() && MayInitialise()) {
      return Initialise(&current, std::move(result));
    }
    have_initial_pose = TrackInitialPose(&current, &result);
  }
  stage.Restart();
  if (!have_initial_pose) return Untracked(&current, std::move(result), "too few pose inliers");

  // 4. Front-end static point determination: Delaunay graph (built in step 3), inconsistent edge
  //    culling, components, largest volume static (Sec. IV, V-A); the others lose their mark.
  //    Beside it, more map points are matched by projection around the initial pose.
  RunFrontEndStaticPoints(&current, &result);
  result.times.static_points_ms = stage.Restart();

  // 5. The pose from static points only.
  const bool tracked = RefinePoseWithStaticPoints(&current, &result);
  result.times.refine_ms = stage.Restart();
  if (!tracked) return Untracked(&current, std::move(result), "too few static inliers");
  //    After a weak episode (people covering the view): the pose checked against the older map.
  ReanchorAfterWeakEpisode(&current, &result);

  // 6. Map management (Sec. V-C): update matched points, keyframe with new points, culling.
  UpdateMatchedPoints(current);
  weak_since_keyframe_ =
      weak_since_keyframe_ || current.pose.num_inliers < config_.tracking.reanchor_weak_inliers;
  if (NeedKeyFrame(current.pose.num_inliers)) {
    result.counts.new_points = MakeKeyFrame(current);
    result.keyframe = true;
    weak_since_keyframe_ = false;
  }
  result.times.mapping_ms = stage.Restart();

  lost_frames_ = 0;
  initialised_ = true;
  result.has_pose = true;
  result.has_previous_pose = result.has_previous_pose && current.relocalisation_inliers == 0;
  result.T_world_camera = current.T_camera_world.inverse();
  result.information = current.pose.information;
  motion_.Update(frame.stamp_s, result.T_world_camera);
  RememberPoseOnNewestKeyFrame(result.frame_index);
  Summarise(current, &result);
  result.times.total_ms = result.times.features_ms + total.ElapsedMs();
  return result;
}

bool Odometry::TrackInitialPose(Current* current, FrameResult* result) {
  Stopwatch stage;
  // 2. Match marked and unmarked local-map points around the predicted pose (Sec. V-B).
  const double stamp_s = current->frame->stamp_s;
  const double max_gap_s = config_.tracking.max_prediction_gap_s;
  const Eigen::Isometry3d T_camera_world_predicted = motion_.Predict(stamp_s, max_gap_s).inverse();
  const bool wide = lost_frames_ > 0 || motion_.IsGap(stamp_s, max_gap_s);
  MatchLocalMapPoints(current, T_camera_world_predicted, wide);
  result->times.matching_ms = stage.Restart();

  // 3. Initial pose by motion-only BA (Huber) over marked points; RANSAC when they are too few.
  //    Beside it, the Delaunay graph of step 4, which needs the matches but not the pose.
  //    When that fails (a jump the prediction missed): match again with the wide radius, then
  //    relocalise by descriptors in the window, then at the places that place recognition names
  //    in the whole keyframe map (SetPlaceLookup).
  const bool have_initial_pose =
      SolveInitialPose(current, T_camera_world_predicted, result->frame_index) ||
      (!wide &&
       RematchAndSolveInitialPose(current, T_camera_world_predicted,
                                  config_.tracking.wide_search_radius_px, result->frame_index)) ||
      Relocalise(current, result->frame_index) ||
      RelocaliseAtNamedPlaces(current, result->frame_index, LostFramePlaces());
  result->times.initial_pose_ms = stage.Restart();
  return have_initial_pose;
}

std::string Odometry::FeatureShortage(const FrameFeatures& features) const {
  const int num_features = static_cast<int>(features.features.size());
  if (num_features >= config_.tracking.min_static_inliers) return "";
  // No pose can reach min_static_inliers inliers; say why instead of "too few pose inliers".
  return "too few features (" + std::to_string(num_features) +
         " ORB keypoints: black, saturated or textureless image?)";
}

bool Odometry::SolveInitialPose(Current* current, const Eigen::Isometry3d& T_camera_world_guess,
                                int frame_index) {
  bool have_pose = false;
  RunSideBySide(
      [&] {
        have_pose = SolvePose(current, T_camera_world_guess, static_cast<uint32_t>(frame_index));
      },
      [&] {
        if (!config_.static_points.enabled) return;
        current->graph =
            BuildFrontEndGraph(map_, current->matches, current->features, config_.static_points);
      });
  return have_pose;
}

bool Odometry::RematchAndSolveInitialPose(Current* current,
                                          const Eigen::Isometry3d& T_camera_world_guess,
                                          double radius_px, int frame_index) {
  current->feature_taken.assign(current->features.features.size(), false);
  current->matches =
      MatchLocalMap(&map_, current->local_points, current->features, *current->frame->camera,
                    T_camera_world_guess, SearchWithin(radius_px, false), &current->feature_taken);
  return SolveInitialPose(current, T_camera_world_guess, frame_index);
}

bool Odometry::CanRelocalise() const {
  return config_.tracking.relocalisation && !map_.window().empty();
}

FrameResult Odometry::Untracked(Current* current, FrameResult result, const char* why) {
  if (initialised_ || !MayInitialise()) return Lost(current, std::move(result), why);
  current->matches.clear();  // points of the map that Initialise replaces
  return Initialise(current, std::move(result));
}

bool Odometry::Relocalise(Current* current, int frame_index) {
  const TrackingConfig& cfg = config_.tracking;
  if (!CanRelocalise()) return false;
  const DescriptorMatchRules rules;
  const std::vector<PointMatch> by_descriptor =
      MatchByDescriptor(map_, WindowMarkedPoints(map_), current->features, rules);
  const uint32_t seed = static_cast<uint32_t>(frame_index) + 2u;  // SolvePose uses +0 and +1
  const PoseResult found =
      EstimateRobustPoseFromMatches(map_, by_descriptor, current->features, *current->frame->camera,
                                    PointSelection::kMarked, config_, seed);
  // A pose that only a minority of the matches agree with is one group's among several (e.g.
  // people not yet unmarked): no relocalisation then.
  if (!EnoughInliers(found) ||
      found.num_inliers < cfg.relocalisation_min_inlier_share * by_descriptor.size()) {
    return false;
  }
  // The local map around the found pose, as if it had been predicted.
  if (!RematchAndSolveInitialPose(current, found.T_camera_world, cfg.search_radius_px,
                                  frame_index)) {
    return false;
  }
  current->relocalisation_inliers = found.num_inliers;
  current->relocalisation_matches = static_cast<int>(by_descriptor.size());
  return true;
}

bool Odometry::BeginFrame(const RgbdFrame& frame, FrameResult* result) {
  bool reset = false;
  if (have_stamp_ && frame.stamp_s < last_stamp_s_) {
    Reset(ResetMode::kNewWorld);
    reset = true;
    result->message = "time went backwards: reset";
  } else if (localising_ && localise_started_ && !localisation_only_ &&
             frame.stamp_s - localise_start_s_ > localise_timeout_s_) {
    Reset(ResetMode::kNewWorld);
    reset = true;
    result->message = "not localised in the loaded keyframe map within " +
                      std::to_string(localise_timeout_s_) + " s: a new map starts";
  }
  if (localising_ && !localise_started_) {
    localise_started_ = true;
    localise_start_s_ = frame.stamp_s;
  }
  have_stamp_ = true;
  last_stamp_s_ = frame.stamp_s;
  result->frame_index = frame_index_++;
  result->stamp_s = frame.stamp_s;
  // The pose tracking goes on from, with the back end's corrections since the previous frame;
  // Lost, Initialise and a relocalised pose clear has_previous_pose again.
  result->has_previous_pose = LastFramePosed();
  result->T_world_previous_camera = motion_.last_pose();
  return reset;
}

FrameResult Odometry::Initialise(Current* current, FrameResult result) {
  const int with_depth = current->features.NumWithDepth();
  if (with_depth < config_.tracking.min_static_inliers * kInitMinPointsFactor) {
    return Lost(current, std::move(result), "too few features with depth to initialise");
  }
  // The first frame defines the world; after a loss the map restarts at the last good pose.
  const bool first = !motion_.has_pose();
  current->T_camera_world = motion_.last_pose().inverse();
  map_.Clear();
  TrackingConfig create = config_.tracking;
  create.max_new_points = with_depth;
  // Even the first map's points wait for verification: a person in the first frame would
  // otherwise be trusted static until the front end catches it.
  CreationContext context{motion_.last_pose(), result.frame_index,
                          config_.static_points.enabled && config_.tracking.verify_frames > 0};
  const std::vector<bool> none(current->features.features.size(), false);
  const std::vector<int> static_neighbourhood(current->features.features.size(), -1);
  const std::vector<PointId> ids =
      CreateMapPoints(current->features, none, static_neighbourhood, context, create, &map_);
  KeyFrame keyframe;
  keyframe.frame_index = result.frame_index;
  keyframe.stamp_s = result.stamp_s;
  keyframe.T_world_camera = motion_.last_pose();
  keyframe.points = ids;
  previous_ = FrameMeasurements();
  keyframe.measurements = MeasurementsOf(*current, ids);
  map_.AddKeyFrame(std::move(keyframe), MapLimits());
  last_keyframe_frame_ = result.frame_index;
  last_keyframe_static_ = static_cast<int>(ids.size());
  last_tracked_ = ids;
  initialised_ = true;
  lost_frames_ = 0;
  motion_.Update(result.stamp_s, motion_.last_pose());
  motion_.ForgetVelocity();
  RememberPoseOnNewestKeyFrame(result.frame_index);
  result.state = TrackingState::kInitialised;
  result.has_pose = first;           // a re-initialisation's pose is assumed, never reported
  result.has_previous_pose = false;  // the map starts here
  result.T_world_camera = motion_.last_pose();
  result.keyframe = true;
  result.counts.new_points = static_cast<int>(ids.size());
  if (!first) result.message = "re-initialised at the last good pose";
  Summarise(*current, &result);
  return result;
}

FrameResult Odometry::Lost(Current* current, FrameResult result, const char* why) {
  result.state = TrackingState::kLost;
  result.has_pose = result.has_previous_pose = false;
  result.message = why;
  ++lost_frames_;
  motion_.ForgetVelocity();
  if (lost_frames_ >= config_.tracking.lost_frames_before_reset) initialised_ = false;
  Summarise(*current, &result);
  return result;
}

}  // namespace dslam
