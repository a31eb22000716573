#pragma once
// Config section `tracking`: local-map tracking, keyframes, map points and tracking loss.
// A member of the one Config tree (config.h).

#include <string>

#include "dslam/core/config_field.h"

namespace dslam {

/// Local-map tracking, keyframe policy, point management and recovery (odometry.h).
struct TrackingConfig {
  int window_keyframes = 12;            ///< [-] keyframes whose points form the local map
  double search_radius_px = 10.0;       ///< [px] projection search radius at octave 0
  double wide_search_radius_px = 30.0;  ///< [px] radius when the narrow search finds too few
  int min_matches = 40;                 ///< [-] fewer matches in the narrow search: search wide
  int min_static_inliers = 20;          ///< [-] fewer static inliers: the pose is not trusted
  /// Frames the front-end point correlations compare with the current one: "keyframes" (up to
  /// front_end_keyframes keyframes spread over the window), "previous" (the paper: the previous
  /// frame) or "both".
  std::string front_end_reference = "keyframes";
  int front_end_keyframes = 6;              ///< [-] keyframes used by "keyframes" / "both"
  int front_end_min_age_frames = 5;         ///< [frames] younger keyframes are not used (too short)
  int keyframe_max_interval = 10;           ///< [frames] a keyframe at least this often
  int keyframe_min_interval = 3;            ///< [frames] and at most this often
  double keyframe_min_tracked_ratio = 0.7;  ///< [-] static matches below this x the last keyframe's
  int keyframe_min_static = 150;            ///< [-] fewer static matches: new keyframe
  int max_new_points = 400;                 ///< [-] map points created per keyframe at most
  /// At keyframes, verified static pose inliers fuse their measurement into the map position
  /// (information-weighted mean; the paper refines marked points by bundle adjustment). Off by
  /// default: on Bonn crowd it raised ATE from 0.10 to 0.24 m (people that stood still, were
  /// verified and fused, then walked off), on synthetic walking it gained 3 mm.
  bool fuse_static_points = false;
  double dynamic_neighbour_radius_px = 40.0;  ///< [px] neighbourhood for new-point labels
  double cull_min_found_ratio = 0.25;  ///< [-] found/visible below this after cull_min_visible
  int cull_min_visible = 8;            ///< [-] sightings before the found ratio is checked
  /// [frames] verified static points that leave the keyframe window (e.g. hidden by a person
  /// standing in front of the camera) stay in the map and the local map this long after they were
  /// last seen, so they are found again when the view clears. 0: only window points.
  int keep_static_frames = 90;
  /// [frames] a new map point is a candidate (not used for the pose while enough verified
  /// points exist) until the front end finds it static at least this long after its creation.
  /// 0: new points are trusted at once (the paper: new points start marked).
  int verify_frames = 6;
  int isolated_frames_to_unmark = 3;  ///< [frames] isolated this often in a row: unmarked
  /// [frames] an unmarked point is marked static again only after the front end found it static
  /// in as many frames in a row as it had been labelled dynamic, but at most this many (a person
  /// who stops is not trusted at once; a static point unmarked by one bad frame is back after
  /// one). 1: at once (before this rule).
  int remark_frames = 15;
  int lost_frames_before_reset = 10;  ///< [frames] lost this long: re-initialise at last pose

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    v(FieldInfo{"window_keyframes", "-", 1, 100, "keyframes whose points form the local map", {}},
      s.window_keyframes);
    v(FieldInfo{"search_radius_px", "px", 1.0, 200.0, "projection search radius (octave 0)", {}},
      s.search_radius_px);
    v(FieldInfo{"wide_search_radius_px",
                "px",
                1.0,
                400.0,
                "search radius when the narrow search finds too few matches",
                {}},
      s.wide_search_radius_px);
    v(FieldInfo{"min_matches", "-", 3, 10000, "fewer narrow matches: search wide", {}},
      s.min_matches);
    v(FieldInfo{"min_static_inliers",
                "-",
                3,
                10000,
                "fewer static pose inliers: fall back to a robust pose / lost",
                {}},
      s.min_static_inliers);
    v(
        FieldInfo{
            "front_end_reference",
            "-",
            0,
            0,
            "frames the front-end correlations compare with: keyframes, previous (paper) or both",
            {"keyframes", "previous", "both"}},
        s.front_end_reference);
    v(FieldInfo{"front_end_keyframes",
                "-",
                1,
                100,
                "keyframes spread over the window used by the front end",
                {}},
      s.front_end_keyframes);
    v(FieldInfo{"front_end_min_age_frames",
                "frames",
                0,
                10000,
                "keyframes younger than this are not compared by the front end",
                {}},
      s.front_end_min_age_frames);
    v(FieldInfo{"keyframe_min_interval", "frames", 1, 1000, "a keyframe at most this often", {}},
      s.keyframe_min_interval);
    v(FieldInfo{"keyframe_max_interval", "frames", 1, 1000, "a keyframe at least this often", {}},
      s.keyframe_max_interval);
    v(FieldInfo{"keyframe_min_tracked_ratio",
                "-",
                0.0,
                1.0,
                "static matches below this share of the last keyframe's: new keyframe",
                {}},
      s.keyframe_min_tracked_ratio);
    v(FieldInfo{"keyframe_min_static", "-", 0, 100000, "fewer static matches: new keyframe", {}},
      s.keyframe_min_static);
    v(FieldInfo{"max_new_points", "-", 0, 100000, "map points created per keyframe", {}},
      s.max_new_points);
    v(FieldInfo{"fuse_static_points",
                "-",
                0,
                1,
                "fuse keyframe measurements of verified static inliers into map positions",
                {}},
      s.fuse_static_points);
    v(FieldInfo{"dynamic_neighbour_radius_px",
                "px",
                0.0,
                1000.0,
                "new points start unmarked when most tracked neighbours within this are dynamic",
                {}},
      s.dynamic_neighbour_radius_px);
    v(FieldInfo{"cull_min_found_ratio", "-", 0.0, 1.0, "found/visible ratio below this: cull", {}},
      s.cull_min_found_ratio);
    v(FieldInfo{"cull_min_visible", "-", 1, 100000, "sightings before the ratio is checked", {}},
      s.cull_min_visible);
    v(FieldInfo{"keep_static_frames",
                "frames",
                0,
                100000,
                "verified static points outside the window stay in the local map this long",
                {}},
      s.keep_static_frames);
    v(FieldInfo{"verify_frames",
                "frames",
                0,
                1000,
                "new points are used for the pose once found static this long after creation "
                "(0: at once, as the paper)",
                {}},
      s.verify_frames);
    v(FieldInfo{"isolated_frames_to_unmark",
                "frames",
                1,
                1000,
                "a point whose graph edges are all inconsistent this many frames in a row is "
                "unmarked (once: probably a false match, only left out of that frame's pose)",
                {}},
      s.isolated_frames_to_unmark);
    v(FieldInfo{"remark_frames",
                "frames",
                1,
                100000,
                "static frames in a row an unmarked point needs (its dynamic frames, at most this)",
                {}},
      s.remark_frames);
    v(FieldInfo{"lost_frames_before_reset",
                "frames",
                1,
                100000,
                "consecutive lost frames before re-initialising at the last good pose",
                {}},
      s.lost_frames_before_reset);
  }
};

}  // namespace dslam
