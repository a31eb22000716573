#pragma once
// The dslam front end: ORB tracking against a local map in which only trusted static (marked)
// points drive motion estimation, with front-end static point determination every frame.

#include <memory>
#include <string>
#include <vector>

#include "dslam/core/config.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/tracking/frame_result.h"
#include "dslam/tracking/front_end_static_points.h"
#include "dslam/tracking/map.h"
#include "dslam/tracking/motion_model.h"
#include "dslam/tracking/place_lookup.h"
#include "dslam/tracking/pose_estimation.h"
#include "dslam/tracking/reanchoring.h"

namespace dslam {

/// What Odometry::Reset keeps of the odometry's world frame.
enum class ResetMode {
  /// The next frame initialises at the last tracked pose: the world frame continues (a `reset`
  /// service keeps the ROS odom frame continuous, REP 105).
  kKeepPose,
  /// The next frame initialises at the world origin: a new run in a new world frame (time went
  /// backwards, e.g. a bag played in a loop).
  kNewWorld,
};

/// What an odometry started in a loaded keyframe map (Odometry::StartInMap) may do with it.
enum class LoadedMapUse {
  /// The loaded map is the start of this run's map: extended, refined, corrected and culled as
  /// the run goes on (save it again to keep the additions).
  kExtend,
  /// Localisation only: the loaded keyframes and points are frozen (Map::Freeze: never moved,
  /// erased, culled or relabelled); keyframes and points this run makes are temporary (a keyframe
  /// is erased once it is out of the window, its points with it when culled), so memory stays
  /// bounded by the loaded map and the window. The run never leaves the loaded map: no timeout
  /// while localising, no re-initialisation after a long loss (frames stay lost until one is
  /// relocalised in the window or at the places the lookup names).
  kLocalisationOnly,
};

/// Which per-frame lists FrameResult carries (the counts are always filled). The lists cost time
/// and memory on every frame; a caller that does not draw them asks for none.
struct FrameRequest {
  bool points = true;  ///< FrameResult::points (matched map points with their labels)
  bool edges = true;   ///< FrameResult::edges (the front-end graph)
};

/// Processes RGB-D frames one at a time. Not thread-safe: call from one thread.
class Odometry {
 public:
  /// Throws ConfigError when `config` is invalid.
  explicit Odometry(const Config& config);

  /// Runs the pipeline of the paper's front end on one frame (see ProcessFrame in odometry.cpp).
  /// A frame older than the previous one (a bag played in a loop) first resets the odometry
  /// into a new world (ResetMode::kNewWorld; FrameResult::reset and message say so). `request`
  /// chooses the per-frame lists filled. Throws std::invalid_argument when frame.Check() fails.
  FrameResult ProcessFrame(const RgbdFrame& frame, const FrameRequest& request = {});
  /// As above with step 1 done already: `features` are ExtractFeatures(frame, config().features,
  /// config().depth_noise), taken in `features_ms` [ms] (Slam extracts them without its map
  /// lock). The results are identical.
  FrameResult ProcessFrame(const RgbdFrame& frame, FrameFeatures features, double features_ms,
                           const FrameRequest& request = {});

  /// Forgets the map and the velocity; the next frame initialises at the last tracked pose
  /// (kKeepPose) or at the world origin (kNewWorld). Frame indices restart at 0.
  void Reset(ResetMode mode);

  /// Starts over in `map` (a loaded keyframe map; its world frame becomes this odometry's): the
  /// motion model is forgotten and frames have no pose (TrackingState::kLocalising) until one is
  /// relocalised in the map at a place `places` names (LocaliseInLoadedMap). When none is within
  /// `timeout_s` [s] of the first frame's stamp, that frame resets into a new world
  /// (ResetMode::kNewWorld: FrameResult::reset and message say so) and a new map starts there;
  /// with LoadedMapUse::kLocalisationOnly there is no timeout, and `places` also serves lost
  /// frames when SetPlaceLookup gave none. Frame indices continue after the newest frame of
  /// `map`. Throws std::invalid_argument when `places` is null, `timeout_s` is not positive,
  /// tracking.relocalisation is off or a keyframe's frame_index is INT_MAX (odometry unchanged).
  void StartInMap(Map map, std::shared_ptr<PlaceLookup> places, double timeout_s,
                  LoadedMapUse use = LoadedMapUse::kExtend);
  /// Between StartInMap and the first frame localised in the map (or its timeout).
  bool localising() const { return localising_; }
  /// StartInMap with LoadedMapUse::kLocalisationOnly, until Reset.
  bool localisation_only() const { return localisation_only_; }
  /// Place recognition over the whole keyframe map for lost frames (null: none, the default):
  /// a frame that cannot be relocalised in the window is tried at the places `places` names
  /// (RelocaliseAtNamedPlaces), so that a tracker lost for long finds a view it left the window
  /// with. Kept across resets.
  void SetPlaceLookup(std::shared_ptr<PlaceLookup> places) { map_places_ = std::move(places); }

  const Map& map() const { return map_; }  ///< the local map (for visualisation)
  /// The local map, for the back end to refine between frames (Slam); call
  /// AdoptNewestKeyFramePose() after changing keyframe poses.
  Map* mutable_map() { return &map_; }

  /// Moves the last tracked pose with the keyframe that was newest when that frame was tracked
  /// (refined by the back end): that keyframe's pose when the frame was made a keyframe,
  /// otherwise the pose relative to it that tracking found. Nothing when it left the window.
  void AdoptNewestKeyFramePose();
  /// [optical frame -> world] Pose of the last tracked frame as tracking goes on from it: the
  /// motion model's last pose, after the back end's corrections (identity before the first).
  const Eigen::Isometry3d& T_world_last_camera() const { return motion_.last_pose(); }
  const Config& config() const { return config_; }

 private:
  /// Working state of the frame being processed.
  struct Current {
    const RgbdFrame* frame = nullptr;
    FrameFeatures features;
    std::vector<bool> feature_taken;
    std::vector<PointId> local_points;  ///< the local map searched in this frame
    std::vector<PointMatch> matches;
    std::vector<bool> excluded;  ///< per match: left out of the refined pose (isolated/dynamic)
    Eigen::Isometry3d T_camera_world = Eigen::Isometry3d::Identity();
    PoseResult pose;
    FrontEndGraph graph;  ///< built beside the initial pose, used by the static points
    FrontEndStaticPoints static_points;
    bool from_robust_pose = false;
    int relocalisation_inliers = 0;  ///< > 0: the pose came from Relocalise (its RANSAC inliers)
    int relocalisation_matches = 0;  ///< the descriptor matches that RANSAC sampled
  };

  bool BeginFrame(const RgbdFrame& frame, FrameResult* result);
  /// Steps 2 and 3 of ProcessFrame: the local map matched around the prediction and the initial
  /// pose from it (with a wider search and relocalisation when that fails). False: no pose.
  bool TrackInitialPose(Current* current, FrameResult* result);
  /// While localising: RelocaliseAtNamedPlaces with `places_`; its success ends localising.
  bool LocaliseInLoadedMap(Current* current, int frame_index);
  /// The places a lost frame is tried at: SetPlaceLookup's, else in localisation-only mode
  /// StartInMap's; null: none.
  PlaceLookup* LostFramePlaces() const;
  /// Whether the map may be re-initialised from a frame (never in localisation-only mode).
  bool MayInitialise() const { return !localisation_only_; }
  /// The window set around each keyframe `places` names for the frame (best first, at most
  /// kPlacesTriedPerFrame, KeyFramesAround) and the frame relocalised there (Relocalise); true
  /// at the first success. False: the window is as it was before.
  bool RelocaliseAtNamedPlaces(Current* current, int frame_index, PlaceLookup* places);
  /// The frame before the loaded map localised it: no pose, TrackingState::kLocalising.
  FrameResult NotLocalised(Current* current, FrameResult result);
  FrameResult Initialise(Current* current, FrameResult result);
  void MatchLocalMapPoints(Current* current, const Eigen::Isometry3d& T_camera_world, bool wide);
  PoseResult SolvePoseFromStaticPoints(const Current& current,
                                       const Eigen::Isometry3d& T_camera_world) const;
  void MatchUnmatchedLocalPoints(Current* current, const Eigen::Isometry3d& T_camera_world,
                                 double radius_px);
  /// The local points not yet matched, projected with `T_camera_world` for `search`. Reads the
  /// map only (no point is written).
  ProjectedLocalMap ProjectUnmatchedLocalPoints(const Current& current,
                                                const Eigen::Isometry3d& T_camera_world,
                                                const LocalMapSearch& search) const;
  /// The local-map search with `radius_px` [px] (marked and unmarked points alike).
  LocalMapSearch SearchWithin(double radius_px, bool count_visible) const;
  /// Pose from static points (verified, else marked) starting at `T_camera_world_guess`; when
  /// they give too few inliers, a RANSAC pose over all matches. Sets current->pose and, on
  /// success, current->T_camera_world. False: too few inliers either way.
  bool SolvePose(Current* current, const Eigen::Isometry3d& T_camera_world_guess,
                 uint32_t ransac_seed);
  /// Why `features` cannot give a pose (fewer than min_static_inliers), or "" when they can.
  std::string FeatureShortage(const FrameFeatures& features) const;
  /// SolvePose and, beside it (in parallel), current->graph for the static points. False: no pose.
  bool SolveInitialPose(Current* current, const Eigen::Isometry3d& T_camera_world_guess,
                        int frame_index);
  /// The whole local map matched again within `radius_px` [px] around `T_camera_world_guess`
  /// (its points were counted visible at the prediction already), then SolveInitialPose.
  /// Replaces current->matches. False: no pose. After the narrow search gave no pose (the
  /// prediction was off by more than search_radius_px: a jerk of the hand, or the first frame
  /// after initialisation, which has no velocity) with wide_search_radius_px; after
  /// relocalisation around its pose.
  bool RematchAndSolveInitialPose(Current* current, const Eigen::Isometry3d& T_camera_world_guess,
                                  double radius_px, int frame_index);
  /// After SolveInitialPose failed (relocalisation.h): descriptor matches against the window's
  /// marked points, a RANSAC pose from them and, around it, the local map searched again and
  /// SolveInitialPose. Replaces current->matches. False: off, too few inliers, or fewer than
  /// relocalisation_min_inlier_share of the descriptor matches.
  bool Relocalise(Current* current, int frame_index);
  /// Whether relocalisation is on and there is a map to relocalise in.
  bool CanRelocalise() const;
  /// A frame whose pose failed (`why`): lost while the map is initialised; after
  /// lost_frames_before_reset lost frames (initialised_ false), the map re-initialised from it
  /// when MayInitialise(), else lost again.
  FrameResult Untracked(Current* current, FrameResult result, const char* why);
  /// RANSAC pose over the matches of `voters` (EstimateRobustPoseFromMatches).
  PoseResult RobustPose(const Current& current, PointSelection voters, uint32_t ransac_seed) const;
  bool EnoughInliers(const PoseResult& pose) const;  ///< success and >= min_static_inliers
  std::vector<const FrameMeasurements*> FrontEndReferenceFrames() const;
  /// Front-end static point determination and, beside it (in parallel), more local-map matches
  /// around the initial pose; those matches are appended after it, not yet judged.
  void RunFrontEndStaticPoints(Current* current, FrameResult* result);
  void DetermineFrontEndLabels(Current* current, FrameResult* result);
  bool RefinePoseWithStaticPoints(Current* current, FrameResult* result);
  /// At the end of a weak episode, the pose checked against the map made before it; a large
  /// enough disagreement moves what was made since, and this frame's and the last frame's poses,
  /// onto the older map (reanchoring.h; FrameResult::reanchored).
  void ReanchorAfterWeakEpisode(Current* current, FrameResult* result);
  void UpdateMatchedPoints(const Current& current);
  bool NeedKeyFrame(int static_matches) const;
  /// The last frame of this world ended with a pose tracking goes on from (tracked, recovered or
  /// (re-)initialised); false after a lost frame and a reset (FrameResult::has_previous_pose).
  bool LastFramePosed() const { return initialised_ && lost_frames_ == 0; }
  /// The keyframe map's limits from tracking.window_keyframes, covisible_keyframes, max_keyframes.
  KeyFrameMapLimits MapLimits() const;
  /// First frame whose verified static points stay in the local map (keep_static_frames); -1: off.
  int StaticSeenSinceFrame() const;
  int MakeKeyFrame(const Current& current);
  FrameMeasurements MeasurementsOf(const Current& current,
                                   const std::vector<PointId>& created) const;
  FrameResult Lost(Current* current, FrameResult result, const char* why);
  void Summarise(const Current& current, FrameResult* result) const;
  /// Fills FrameResult::points / edges as `request_` asks.
  void AddViews(const Current& current, FrameResult* result) const;

  Config config_;
  FrameRequest request_;  ///< of the frame being processed
  Map map_;
  ConstantVelocityModel motion_;
  FrameMeasurements previous_;         ///< measurements of the previous tracked frame
  std::vector<PointId> last_tracked_;  ///< points matched in the previous tracked frame
  bool initialised_ = false;
  bool have_stamp_ = false;
  double last_stamp_s_ = 0.0;
  int frame_index_ = 0;
  int lost_frames_ = 0;
  int last_keyframe_frame_ = 0;
  int last_keyframe_static_ = 0;
  WeakEpisode weak_episode_;  ///< reanchoring.h
  /// StartInMap's, until localised (localisation-only: kept for lost frames) or reset
  std::shared_ptr<PlaceLookup> places_;
  std::shared_ptr<PlaceLookup> map_places_;  ///< SetPlaceLookup's, for lost frames
  bool localising_ = false;                  ///< StartInMap was called and no frame localised yet
  bool localisation_only_ = false;           ///< StartInMap's LoadedMapUse::kLocalisationOnly
  double localise_timeout_s_ = 0.0;          ///< [s] StartInMap's timeout
  bool localise_started_ = false;            ///< a frame was processed since StartInMap
  double localise_start_s_ = 0.0;            ///< [s] stamp of that first frame
  /// A pose with fewer than reanchor_weak_inliers inliers was tracked since the last keyframe.
  bool weak_since_keyframe_ = false;

  /// The last tracked frame's pose on the keyframe newest at the time (AdoptNewestKeyFramePose).
  struct PoseOnKeyFrame {
    int keyframe_id = -1;
    int frame_index = -1;
    Eigen::Isometry3d T_keyframe_camera = Eigen::Isometry3d::Identity();
  };
  void RememberPoseOnNewestKeyFrame(int frame_index);
  PoseOnKeyFrame last_on_keyframe_;
};

}  // namespace dslam
