#pragma once
// Config section `tracking`: local-map tracking, keyframes, map points and tracking loss.
// A member of the one Config tree (config.h).

#include <string>

#include "dslam/core/config_field.h"

namespace dslam {

/// Local-map tracking, keyframe policy, point management and recovery (odometry.h). Units, ranges
/// and meanings of the fields are given in Fields() (printed by `dslam_config_doc`).
struct TrackingConfig {
  int window_keyframes = 12;
  int covisible_keyframes = 0;
  int max_keyframes = 300;
  double search_radius_px = 10.0;
  bool follow_last_measurement = true;
  double wide_search_radius_px = 30.0;
  int min_matches = 40;
  int min_static_inliers = 20;
  int front_end_keyframes = 6;
  int front_end_min_age_frames = 5;
  int keyframe_max_interval = 10;
  int keyframe_min_interval = 3;
  double keyframe_min_tracked_ratio = 0.7;
  int keyframe_min_static = 150;
  int max_new_points = 400;
  double dynamic_neighbour_radius_px = 40.0;
  double cull_min_found_ratio = 0.25;
  int keep_static_frames = 90;
  int verify_frames = 6;
  int isolated_frames_to_unmark = 3;
  int remark_frames = 15;
  int lost_frames_before_reset = 10;
  double max_prediction_gap_s = 1.0;
  bool relocalisation = true;
  double relocalisation_min_inlier_share = 0.5;
  bool reanchoring = true;
  int reanchor_weak_inliers = 60;
  int reanchor_strong_inliers = 120;
  double reanchor_min_correction_m = 0.03;
  double reanchor_min_correction_deg = 1.0;

  /// Visits every field in documentation order.
  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    SearchFields(s, v);
    FrontEndAndKeyFrameFields(s, v);
    PointFields(s, v);
  }

 private:
  // Local-map search and pose trust.
  template <typename Self, typename Visitor>
  static void SearchFields(Self& s, Visitor& v) {
    v(Field("window_keyframes", "-", 1, 100,
            "newest keyframes in the window (whose points form the local map)"),
      s.window_keyframes);
    // Chosen by covisibility with the newest keyframe or by a nearby camera (keyframe_window.h):
    // a camera that returns to a view searches the points it made there, and the back end's
    // window ties the new keyframes to them. 0: the window is the newest keyframes alone.
    v(Field("covisible_keyframes", "-", 0, 100, "older map keyframes added to the window"),
      s.covisible_keyframes);
    // Beyond it the oldest keyframes outside the window are erased (and their points with them,
    // when no other keyframe observes them); redundant ones go first (Map::AddKeyFrame).
    v(Field("max_keyframes", "-", 1, 100000, "keyframes the map keeps (at least the window's)"),
      s.max_keyframes);
    v(Field("search_radius_px", "px", 1.0, 200.0, "projection search radius (octave 0)"),
      s.search_radius_px);
    // A marked point's map position is where it was created; projected
    // from its measurement in the last tracked frame instead, more points stay matched where
    // that position has aged (LocalMapSearch::last_frame, local_map_matching.h). On by default:
    // Bonn crowd 300-599 tracks 300 of 300 frames (294 without), mean ATE over seeds 1-5
    // walking_static 18.7 -> 15.4 mm, walking_halfsphere 22.3 -> 20.8 (docs/benchmarks/backend.md).
    v(Flag("follow_last_measurement",
           "search marked points measured in the last tracked frame around that measurement "
           "instead of their map position"),
      s.follow_last_measurement);
    v(Field("wide_search_radius_px", "px", 1.0, 400.0,
            "search radius when the narrow search finds too few matches"),
      s.wide_search_radius_px);
    v(Field("min_matches", "-", 3, 10000, "fewer narrow matches: search wide"), s.min_matches);
    v(Field("min_static_inliers", "-", 3, 10000,
            "fewer static pose inliers: fall back to a robust pose / lost"),
      s.min_static_inliers);
  }

  // Front-end reference frames and the keyframe policy.
  template <typename Self, typename Visitor>
  static void FrontEndAndKeyFrameFields(Self& s, Visitor& v) {
    // The front end compares each frame with keyframes spread over the window (the paper: the
    // previous frame, which lost: BENCHMARKS.md, "Issue 50: switches no measurement chose").
    v(Field("front_end_keyframes", "-", 1, 100,
            "keyframes spread over the window used by the front end"),
      s.front_end_keyframes);
    v(Field("front_end_min_age_frames", "frames", 0, 10000,
            "keyframes younger than this are not compared by the front end"),
      s.front_end_min_age_frames);
    v(Field("keyframe_min_interval", "frames", 1, 1000, "a keyframe at most this often"),
      s.keyframe_min_interval);
    v(Field("keyframe_max_interval", "frames", 1, 1000, "a keyframe at least this often"),
      s.keyframe_max_interval);
    v(Field("keyframe_min_tracked_ratio", "-", 0.0, 1.0,
            "static matches below this share of the last keyframe's: new keyframe"),
      s.keyframe_min_tracked_ratio);
    v(Field("keyframe_min_static", "-", 0, 100000, "fewer static matches: new keyframe"),
      s.keyframe_min_static);
  }

  // Map point creation, fusion, culling, marking and tracking loss.
  template <typename Self, typename Visitor>
  static void PointFields(Self& s, Visitor& v) {
    v(Field("max_new_points", "-", 0, 100000, "map points created per keyframe"), s.max_new_points);
    v(Field("dynamic_neighbour_radius_px", "px", 0.0, 1000.0,
            "new points start unmarked when most tracked neighbours within this are dynamic"),
      s.dynamic_neighbour_radius_px);
    // Checked once a point was visible in 8 frames (kCullMinVisible, odometry_keyframes.cpp).
    v(Field("cull_min_found_ratio", "-", 0.0, 1.0, "found/visible ratio below this: cull"),
      s.cull_min_found_ratio);
    // E.g. points hidden by a person standing in front of the camera are found again when the
    // view clears. 0: only window points.
    v(Field("keep_static_frames", "frames", 0, 100000,
            "verified static points outside the window stay in the local map this long"),
      s.keep_static_frames);
    // Until then a new point is a candidate, not used for the pose while enough verified points
    // exist.
    v(Field("verify_frames", "frames", 0, 1000,
            "new points are used for the pose once found static this long after creation "
            "(0: at once, as the paper)"),
      s.verify_frames);
    v(Field("isolated_frames_to_unmark", "frames", 1, 1000,
            "a point whose graph edges are all inconsistent this many frames in a row is "
            "unmarked (once: probably a false match, only left out of that frame's pose)"),
      s.isolated_frames_to_unmark);
    // A person who stops is not trusted at once; a static point unmarked by one bad frame is back
    // after one. 1: at once (before this rule).
    v(Field("remark_frames", "frames", 1, 100000,
            "static frames in a row an unmarked point needs (its dynamic frames, at most this)"),
      s.remark_frames);
    v(Field("lost_frames_before_reset", "frames", 1, 100000,
            "consecutive lost frames before re-initialising at the last good pose (with "
            "relocalisation: at the first later frame that cannot be relocalised)"),
      s.lost_frames_before_reset);
    // After a longer gap (dropped frames, a paused driver) the last velocity says nothing about
    // where the camera is now: predict the last pose and search wide instead of extrapolating.
    v(Field("max_prediction_gap_s", "s", 0.001, 3600.0,
            "longest time since the last tracked frame over which the motion model extrapolates; "
            "longer: last pose and wide search"),
      s.max_prediction_gap_s);
    // When the pose prediction fails (relocalisation.h): no prediction needed, marked points only;
    // descriptor matches by DescriptorMatchRules' defaults.
    v(Flag("relocalisation",
           "when tracking fails, match the frame by descriptor against the window's marked "
           "points and take a RANSAC pose from them"),
      s.relocalisation);
    // Measured (docs/benchmarks/loop-closing.md): true relocalisations after dropped frames
    // 0.94-0.95; poses of people not yet unmarked on Bonn crowd 0.27, on walking_halfsphere 0.39.
    v(Field("relocalisation_min_inlier_share", "-", 0.0, 1.0,
            "a relocalised pose needs at least this share of the descriptor matches as inliers"),
      s.relocalisation_min_inlier_share);
    ReanchorFields(s, v);
  }

  // After a weak episode (reanchoring.h): the pose checked against the map made before it.
  template <typename Self, typename Visitor>
  static void ReanchorFields(Self& s, Visitor& v) {
    v(Flag("reanchoring",
           "after a weak episode, check the pose against the verified points made before it and "
           "move what was made since onto them when they disagree"),
      s.reanchoring);
    v(Field("reanchor_weak_inliers", "-", 1, 100000,
            "a weak episode begins at a pose with fewer inliers than this"),
      s.reanchor_weak_inliers);
    v(Field("reanchor_strong_inliers", "-", 1, 100000,
            "the episode is checked at a pose with at least this many inliers again"),
      s.reanchor_strong_inliers);
    v(Field("reanchor_min_correction_m", "m", 0.0, 100.0,
            "smallest translation of a correction that is applied (with min_correction_deg)"),
      s.reanchor_min_correction_m);
    v(Field("reanchor_min_correction_deg", "deg", 0.0, 180.0,
            "smallest rotation of a correction that is applied (either bound moves the map)"),
      s.reanchor_min_correction_deg);
  }
};

}  // namespace dslam
