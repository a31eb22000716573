#pragma once
// Config section `backend`: local mapping after each keyframe (static point determination and
// local bundle adjustment over the keyframe window). A member of the one Config tree (config.h).

#include "dslam/core/config_field.h"

namespace dslam {

/// Local mapping (paper Sec. V, back end): static point determination over the keyframe window
/// (Algorithm 1), then bundle adjustment of the window's keyframes and the verified static points
/// they measure. Units, ranges and meanings of the fields are given in
/// Fields() (printed by `dslam_config_doc`).
struct BackendConfig {
  bool enabled = false;
  int spd_min_dynamic_points = 10;
  double spd_rotation_sigma_deg = 0.3;
  int ba_fixed_keyframes = 3;
  double ba_max_correction_chi2 = 16.81;
  double ba_max_correction_m = 0.05;
  double ba_max_correction_deg = 2.0;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    // Off by default until it beats the front end alone on every benchmark sequence. Measured
    // last in docs/benchmarks/backend.md, "Issue 32, part 6" (mean ATE, off -> on): Bonn 0.0566 ->
    // 0.0556, close_person 0.0199 -> 0.0168, room_tour (with loop closing) 0.120 -> 0.036, but TUM
    // rpy 0-119 0.0324 -> 0.0336, walking over 20 seeds 0.068 -> 0.072 and walking_static 0.015 ->
    // 0.050 (one seed jumps while a walker fills the view). Its BA rejects 20-40 % of the
    // measurements on real data (rpy: the inliers fit, chi2/dof 0.9-1.06; the rest is a tail).
    v(Flag("enabled", "local mapping after each keyframe; off = front end alone"), s.enabled);
    // Algorithm 1 (window_static_points.h) runs before local BA (with static_points.enabled),
    // which then uses the points that stayed marked. Window keyframes sharing fewer than 20
    // measured points with the new keyframe are left out (kMinCovisiblePoints,
    // window_static_points.cpp).
    // Components this small are cut off by a bad measurement more often than by motion over a
    // window (window_static_points.cpp, ComponentsLosingMarks); the same count as
    // static_points.min_static_points, the smallest component that may be the static world.
    v(Field("spd_min_dynamic_points", "-", 1, 1000000,
            "window components with fewer points keep their marks"),
      s.spd_min_dynamic_points);
    // Each keyframe's rotation error turns an edge l into an error of about l x dtheta in its
    // measurement; the front end's pose information does not see drift, so this sigma is added
    // to every window measurement's covariance (CorrelationInput::rotation_covariance). 0.3 deg
    // was measured better than 0 and 0.1 on the synthetic crowds (`git show 0da3eda:BENCHMARKS.md`,
    // section "Back end, part 2"; removed from the current file by bf56fd9); 0 tests with the
    // points' noise alone.
    v(Field("spd_rotation_sigma_deg", "deg", 0.0, 10.0,
            "rotation uncertainty of a window keyframe in the edge tests"),
      s.spd_rotation_sigma_deg);
    // The oldest keyframes of the window keep their poses: they fix the gauge (world frame) and
    // tie the window to the trajectory already estimated. Local BA's other rules are constants of
    // local_bundle_adjustment.cpp; its Huber width and chi-square bound are pose.huber_delta_depth
    // and pose.chi2_depth (the same whitened 3-dof residual as the motion-only BA's).
    v(Field("ba_fixed_keyframes", "-", 1, 100, "oldest window keyframes held fixed in local BA"),
      s.ba_fixed_keyframes);
    // 99% quantile of chi-square with 6 dof: the back end may refine a keyframe within what its
    // own frame's measurements allow, not drag it away (e.g. towards a person in the window).
    v(Field("ba_max_correction_chi2", "-", 0.0, 1e9,
            "a solution moving a keyframe by more than this squared Mahalanobis distance under "
            "the front end's pose information is not applied"),
      s.ba_max_correction_chi2);
    v(Field("ba_max_correction_m", "m", 0.0, 100.0,
            "a solution moving a keyframe further than this is not applied"),
      s.ba_max_correction_m);
    v(Field("ba_max_correction_deg", "deg", 0.0, 180.0,
            "a solution rotating a keyframe more than this is not applied"),
      s.ba_max_correction_deg);
  }
};

}  // namespace dslam
