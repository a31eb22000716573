#pragma once
// Config section `loop_closing`: recognising a place seen before and correcting the keyframe map
// (loop_closing part). A member of the one Config tree (config.h).

#include "dslam/core/config_field.h"

namespace dslam {

/// Loop detection (bag of words over the keyframes' verified static points), geometric
/// verification on static points only, and correction by a pose graph. Units, ranges and
/// meanings of the fields are given in Fields() (printed by `dslam_config_doc`).
struct LoopClosingConfig {
  bool enabled = true;
  int min_frames_apart = 150;
  int consistent_keyframes = 3;
  double min_score_ratio = 0.1;
  int min_inliers = 40;
  double min_inlier_share = 0.3;
  int min_image_quadrants = 3;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    // Needs the back end's keyframe map: off whenever backend.enabled is false. LoopClosing
    // (loop_closing.h) in dslam_run_dataset and in the node, as one of Slam's keyframe observers.
    v(Flag("enabled", "look for loops at each keyframe and correct the keyframe map"), s.enabled);
    v(Field("min_frames_apart", "frames", 1, 1000000,
            "a loop candidate was made at least this many frames before the query keyframe"),
      s.min_frames_apart);
    v(Field("consistent_keyframes", "-", 1, 20,
            "consecutive query keyframes whose candidates agree before a loop is verified"),
      s.consistent_keyframes);
    // The words are the map points' descriptors (loop_detector.h), so covisible keyframes share
    // many words exactly and score high: ORB-SLAM2's 0.6 closed no loop on room_tour seed 1,
    // 0.3 none, 0.1 the three true ones (docs/benchmarks/loop-closing.md, "Issue 33, part 2").
    v(Field("min_score_ratio", "-", 0.0, 10.0,
            "a candidate scores at least this times the query's best covisible keyframe"),
      s.min_score_ratio);
    v(Field("min_inliers", "-", 3, 100000,
            "RANSAC inliers (verified static points of both keyframes) of an accepted loop"),
      s.min_inliers);
    v(Field("min_inlier_share", "-", 0.0, 1.0,
            "inliers of an accepted loop as a share of its descriptor matches"),
      s.min_inlier_share);
    v(Field("min_image_quadrants", "-", 1, 4,
            "image quadrants of the query keyframe the inliers must reach"),
      s.min_image_quadrants);
  }
};

}  // namespace dslam
