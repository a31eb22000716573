#pragma once
// The odometry's keyframe map: map points (marked = trusted static, unmarked = seen moving) and the
// keyframes that observed them. The map keeps keyframes beyond the window (up to a cap, culling
// redundant ones); the window, the keyframes whose points tracking searches and the back end
// refines, is the newest keyframes, plus older ones chosen by covisibility when
// tracking.covisible_keyframes > 0 (0 by default; keyframe_window.h) or the map is frozen
// (localisation only: loaded keyframes around the pose), so that a camera returning to a view
// finds the points it made there. Not thread-safe: Slam
// (backend/slam.h) owns the live map and guards it with its map mutex; the tracking thread changes
// it in Odometry::ProcessFrame, and the back end copies the window into a LocalMappingJob and
// applies the job's results under that mutex (slam.h states the locking policy).

#include <algorithm>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/core/depth_uncertainty.h"

namespace dslam {

using PointId = int64_t;

/// One 3D landmark. Positions are in the world frame [m].
struct MapPoint {
  PointId id = -1;                                          ///< assigned by Map::AddPoint
  Eigen::Vector3d p_world = Eigen::Vector3d::Zero();        ///< position [m], world frame
  Eigen::Matrix3d cov_world = Eigen::Matrix3d::Identity();  ///< position covariance [m^2]
  cv::Mat descriptor;  ///< 1x32 CV_8U ORB descriptor matched against: the creating observation's
  int octave = 0;      ///< pyramid level of that observation
  int created_feature = -1;           ///< index of that observation's feature in its frame
  double reference_distance_m = 0.0;  ///< [m] camera distance of that observation
  bool marked = true;  ///< not known to move: only marked points drive motion estimation
  /// New and not yet verified static over a long enough baseline: matched (so it claims its
  /// feature) but used for the pose only when verified points are too few.
  bool candidate = false;
  int created_frame = 0;    ///< frame index of creation
  int last_seen_frame = 0;  ///< last frame index where it was matched
  int times_visible = 0;    ///< frames where it projected into the image
  int times_found = 0;      ///< frames where it was matched
  int isolated_frames = 0;  ///< consecutive frames in which all its graph edges were inconsistent
  int static_streak = 0;    ///< unmarked point: consecutive frames the front end found it static
  int dynamic_frames = 0;   ///< frames labelled dynamic since it was last marked
  int observing_keyframes = 0;  ///< map keyframes (window and archive) listing it in `points`

  /// Marked and verified: drives motion estimation.
  bool IsVerifiedStatic() const { return marked && !candidate; }
  /// Marked but not yet verified (new point): used for the pose only when verified ones are few.
  bool IsCandidate() const { return marked && candidate; }

  /// Found moving (the front end's dynamic label, or the window's static point determination,
  /// paper Algorithm 1): the point loses its mark and its candidacy, its static streak restarts,
  /// and `dynamic_frames` counts one more frame of evidence, at least `min_dynamic_frames` (the
  /// front end passes 0; the back end tracking.remark_frames, since its evidence spans a window).
  void Unmark(int min_dynamic_frames) {
    marked = false;
    candidate = false;
    static_streak = 0;
    dynamic_frames = std::max(dynamic_frames + 1, min_dynamic_frames);
  }

  /// Labelled static in one more frame (front end): an unmarked point is marked again once its
  /// static streak reaches min(`remark_frames`, `dynamic_frames`), so that a point unmarked by
  /// one bad frame comes back at once and one seen moving long needs up to remark_frames.
  void LookedStatic(int remark_frames) {
    if (!marked && ++static_streak >= std::min(remark_frames, dynamic_frames)) {
      marked = true;
      dynamic_frames = 0;
    }
  }
};

/// RGB-D measurements of map points in one frame, with that frame's pose: the raw material of
/// point-correlation measurements z_ijk = y_ik - y_jk (paper Eq. meas_con_imp).
struct FrameMeasurements {
  Eigen::Isometry3d T_camera_world = Eigen::Isometry3d::Identity();  ///< world -> optical frame
  std::unordered_map<PointId, PointMeasurement> by_point;            ///< y and C per measured point
};

/// A keyframe: the pose of a frame that created map points.
struct KeyFrame {
  int id = -1;           ///< sequential keyframe id
  int frame_index = 0;   ///< index of the frame it was made from
  double stamp_s = 0.0;  ///< [s]
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  std::vector<PointId> points;     ///< map points it observed (created or matched) when it was made
  FrameMeasurements measurements;  ///< y and C of those points measured with depth in it
  /// [-] 6x6 information of the front end's pose of this keyframe (PoseResult::information: order
  /// [dtheta, dt] of a left perturbation of T_camera_world); zero when unknown (first keyframe).
  Eigen::Matrix<double, 6, 6> information = Eigen::Matrix<double, 6, 6>::Zero();
  /// A pose tracked since the previous keyframe (this keyframe's included) had fewer than
  /// tracking.reanchor_weak_inliers inliers: the motion from the previous keyframe rests on a weak
  /// episode (a loop's pose graph trusts it less, loop_correction.h).
  bool weak_since_previous = false;
};

/// A correction of the part of the map made from `first_frame` on (Map::MoveMadeSince). The
/// newest pose takes all of T_new_old; each keyframe made since takes the share of it that
/// `share` gives (PartialCorrection), so that an error that grew over several keyframes is taken
/// back where it grew. Keyframes not in `share` take all of it.
struct MapCorrection {
  int first_frame = -1;  ///< frame index the moved keyframes and points were made from
  /// [world_new <- world_old] the correction of the newest pose
  Eigen::Isometry3d T_new_old = Eigen::Isometry3d::Identity();
  /// [m] world point a partial correction's rotation turns about
  Eigen::Vector3d pivot_world = Eigen::Vector3d::Zero();
  std::map<int, double> share;  ///< [0, 1] by keyframe id: the share of the correction it takes
};

/// [world_new <- world_old] Share `s` [0, 1] of `correction`: the rotation of T_new_old by s times
/// its angle about pivot_world, and s times the displacement T_new_old gives the pivot. s = 1 is
/// T_new_old, s = 0 the identity.
Eigen::Isometry3d PartialCorrection(const MapCorrection& correction, double s);

/// How many keyframes the window and the map hold (TrackingConfig: window_keyframes,
/// covisible_keyframes, max_keyframes).
struct KeyFrameMapLimits {
  int recent_keyframes = 12;    ///< the newest keyframes, always in the window
  int covisible_keyframes = 0;  ///< older keyframes added to the window (keyframe_window.h)
  int max_keyframes = 12;       ///< keyframes the map keeps, window included (the cap)

  /// A window of the newest `n` keyframes alone; older ones are erased.
  static KeyFrameMapLimits Newest(int n) { return {n, 0, n}; }
};

/// Everything a keyframe map holds, as plain lists with their ids (Map::Contents, FromContents;
/// a saved keyframe map).
struct MapContents {
  std::vector<MapPoint> points;     ///< ids ascending
  std::vector<KeyFrame> keyframes;  ///< window and archive, ids ascending (oldest first)
};

/// Map points, the keyframe window and the archived keyframes (the rest of the keyframe map).
class Map {
 public:
  /// The map's points and keyframes (window and archive), each list by id ascending.
  MapContents Contents() const;
  /// A map of `contents`: ids kept, the next ids after the largest, every keyframe archived (no
  /// window until SetWindowTo or AddKeyFrame), observing_keyframes counted from the keyframes'
  /// point lists, ids in keyframe lists that name no point dropped. Throws std::invalid_argument
  /// when a point or keyframe id is negative, repeats or is its type's largest (next id overflows).
  static Map FromContents(MapContents contents);
  /// Makes the keyframes with `ids` (those in the map) the window, the newest `recent` of them
  /// recent (negative: all); the others go to the archive (none is erased). For a tracker that
  /// relocalises at a place that place recognition chose, and that restores its window after.
  void SetWindowTo(const std::vector<int>& ids, int recent = -1);

  /// Freezes every keyframe and point now in the map (a loaded map used for localisation only,
  /// Odometry::StartInMap): the map never moves, erases or culls them (MoveMadeSince,
  /// CorrectKeyFrames, Cull, AddKeyFrame skip them), writers of points reach only unfrozen ones
  /// (FindWritable), and keyframes added later are temporary: AddKeyFrame erases each as soon as
  /// it is out of the window. Clear ends it.
  void Freeze();
  /// Freeze was called since construction or the last Clear.
  bool frozen() const { return frozen_; }
  /// Whether keyframe `id` was in the map when it was frozen.
  bool IsFrozenKeyFrame(int id) const { return frozen_ && id < frozen_keyframes_end_; }
  /// Whether point `id` was in the map when it was frozen.
  bool IsFrozenPoint(PointId id) const { return frozen_ && id < frozen_points_end_; }
  /// The point with `id` for changing it: nullptr when it was culled or is frozen.
  MapPoint* FindWritable(PointId id);

  /// Adds a point, assigns and returns its id.
  PointId AddPoint(MapPoint point);

  /// The point with `id`, or nullptr when it was culled.
  MapPoint* Find(PointId id);
  const MapPoint* Find(PointId id) const;

  /// Removes a point (no-op when absent).
  void Erase(PointId id);

  /// Appends a keyframe (its id is assigned), chooses the window for it (SelectKeyFrameWindow),
  /// archives the keyframes that left the window, erases those of them that are redundant now
  /// (map.cpp: kRedundantShare of their points observed by kRedundantObservers other keyframes)
  /// and then the oldest archived ones beyond `limits.max_keyframes` (at least the window's size).
  /// A frozen map (Freeze) erases every archived keyframe that is not frozen instead, and never a
  /// frozen one: it holds its frozen keyframes and the window.
  const KeyFrame& AddKeyFrame(KeyFrame keyframe, const KeyFrameMapLimits& limits);

  /// The window's keyframes, oldest first (ids ascending); the newest keyframe is last.
  const std::deque<KeyFrame>& window() const { return keyframes_; }
  /// Index in window() of the oldest of the newest `recent_keyframes` (0 without older
  /// covisible keyframes in the window).
  size_t first_recent_keyframe() const { return keyframes_.size() - recent_in_window_; }
  /// Keyframes of the map outside the window, by id.
  const std::map<int, KeyFrame>& archived_keyframes() const { return archive_; }
  /// Keyframes in the map: window and archive.
  size_t num_keyframes() const { return keyframes_.size() + archive_.size(); }
  /// Every keyframe of the map (window and archive), oldest first (ids ascending, which is the
  /// order they were made in).
  std::vector<const KeyFrame*> AllKeyFrames() const;
  /// The window for the back end to refine poses and drop measurements (ids and order stay).
  std::deque<KeyFrame>& mutable_window() { return keyframes_; }

  /// Ids of the points observed by the keyframes in the window plus `extra`, plus verified static
  /// points (marked, not candidates) last seen at or after `static_seen_since_frame` (a negative
  /// value: none), without duplicates and without culled points: the local map tracking searches.
  /// The recently seen ones come from a list of points added or seen (MarkSeen), not from a walk
  /// over every point, so the cost does not grow with the map; `static_seen_since_frame` must not
  /// decrease between calls on one map (it follows the frame index; Clear starts over).
  /// Sets the point's last_seen_frame to `frame` (a frame index) and lists it for LocalPoints.
  void MarkSeen(MapPoint* point, int frame);
  std::vector<PointId> LocalPoints(const std::vector<PointId>& extra,
                                   int static_seen_since_frame = -1) const;

  /// Removes points that are neither referenced by a map keyframe nor seen since
  /// `oldest_frame_to_keep` (verified static points: since `static_seen_since_frame`, when it is
  /// earlier), and points whose found/visible ratio fell below `min_found_ratio` after
  /// `min_visible` sightings; never a frozen point. Returns the number removed.
  int Cull(int oldest_frame_to_keep, double min_found_ratio, int min_visible,
           int static_seen_since_frame = -1);

  /// A map of the keyframe window alone: the keyframes and every point they reference (in
  /// `points` or `measurements`), with the same ids; for the back end to work on while tracking
  /// goes on with this map.
  Map WindowCopy() const;

  /// The keyframe with `id` (window or archive), or nullptr when it was erased.
  KeyFrame* FindKeyFrame(int id);
  const KeyFrame* FindKeyFrame(int id) const;

  /// Moves what was made from frame correction.first_frame on: each keyframe (window and
  /// archive) with frame_index >= first_frame by its share of the correction, each point with
  /// created_frame >= first_frame (position and covariance) with the newest of those keyframes
  /// made at or before its creation (all of the correction when there is none); counts a
  /// correction. Frozen keyframes and points stay (as in CorrectKeyFrames).
  void MoveMadeSince(const MapCorrection& correction);
  /// Moves keyframes by a loop correction: each keyframe with an entry in
  /// `T_world_camera_corrected` (by id) by corrected * before^-1, before being its entry in
  /// `T_world_camera_before` (the pose the correction was computed from; its present pose when
  /// absent), so that a change made since (local BA) is kept; keyframes without one and newer
  /// (by id) than every keyframe with one move with the newest of those (made while the
  /// correction was computed); each point with the newest moved keyframe made at or before its
  /// creation frame (position and covariance). Frozen keyframes and points stay where they are
  /// (Freeze). Counts a correction. Poses [m], camera optical frame -> world.
  void CorrectKeyFrames(const std::map<int, Eigen::Isometry3d>& T_world_camera_corrected,
                        const std::map<int, Eigen::Isometry3d>& T_world_camera_before = {});
  /// Corrections made by MoveMadeSince and CorrectKeyFrames since construction (Clear keeps the
  /// count): a copy of the window taken before a correction must not write its poses back after it.
  uint64_t corrections() const { return corrections_; }

  /// The id the next AddPoint assigns: points with ids from here on are newer than this moment.
  PointId next_point_id() const { return next_point_id_; }
  /// Raises the ids the next AddPoint and AddKeyFrame assign to at least those `earlier`'s would
  /// assign, so that ids stay unique when this map replaces `earlier` (a loaded map started in
  /// again after a reset).
  void ContinueIdsAfter(const Map& earlier);
  size_t size() const { return points_.size(); }  ///< number of map points
  void Clear();  ///< removes every point and keyframe, and ends Freeze

 private:
  /// Moves each keyframe (window and archive) by [world_new <- world_old] correction_of(it) when
  /// that gives one, and each point with created_frame >= min_created_frame with the newest moved
  /// keyframe made at or before its creation frame (by *before_first when there is none; not at
  /// all when before_first is null); frozen keyframes and points stay. Counts a correction.
  void MoveKeyFramesAndPoints(
      const std::function<std::optional<Eigen::Isometry3d>(const KeyFrame&)>& correction_of,
      int min_created_frame, const Eigen::Isometry3d* before_first);
  /// Adds `delta` to observing_keyframes of the points `keyframe` lists.
  void CountObservations(const KeyFrame& keyframe, int delta);
  /// Makes the keyframes with `window_ids` the window; the others go to the archive.
  void SetWindow(const std::vector<int>& window_ids, int recent_keyframes);
  /// SetWindow without erasing: returns the ids of the keyframes it archived.
  std::vector<int> MoveWindow(const std::vector<int>& window_ids, int recent_keyframes);
  /// Whether most points of `keyframe` are observed by enough other keyframes.
  bool IsRedundant(const KeyFrame& keyframe) const;
  /// Erases archived keyframes with ids in `ids` that are redundant and not frozen.
  void EraseRedundant(const std::vector<int>& ids);
  /// Erases archived keyframes with ids >= `first_id`, oldest first, while the map holds more
  /// than `max_keyframes`.
  void EraseArchived(int first_id, size_t max_keyframes);

  std::unordered_map<PointId, MapPoint> points_;
  /// Every point added (AddPoint, FromContents) or seen (MarkSeen) since it was last dropped,
  /// once: LocalPoints reads these instead of every point and drops those erased or last seen
  /// before its static_seen_since_frame (so the list is as long as the recently seen part of the
  /// map, whatever the map's size). Mutable: LocalPoints prunes it as it reads; the map's users
  /// hold Slam's map lock, so no two threads call it at once.
  mutable std::vector<PointId> recently_seen_;
  mutable std::unordered_set<PointId> recently_seen_set_;
  std::deque<KeyFrame> keyframes_;
  std::map<int, KeyFrame> archive_;
  size_t recent_in_window_ = 0;
  PointId next_point_id_ = 0;
  int next_keyframe_id_ = 0;
  uint64_t corrections_ = 0;
  bool frozen_ = false;            ///< Freeze
  int frozen_keyframes_end_ = 0;   ///< keyframes with smaller ids are frozen (when frozen_)
  PointId frozen_points_end_ = 0;  ///< points with smaller ids are frozen (when frozen_)
};

}  // namespace dslam
