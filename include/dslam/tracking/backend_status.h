#pragma once
// What the back end reports after a keyframe: the stats each of its stages returns (local bundle
// adjustment, backend/local_bundle_adjustment.h; static point determination over the window,
// backend/window_static_points.h) and BackEndStatus, which embeds them. Plain structs here, in
// tracking, so that FrameResult (frame_result.h) carries them without the back end's headers.

#include "dslam/static_points/static_points_stats.h"

namespace dslam {

/// What one local bundle adjustment did.
struct LocalBaStats {
  bool ran = false;  ///< false: too few keyframes or points (nothing changed)
  /// [-] window keyframes after the oldest `ba_fixed_keyframes`: free, except those that
  /// measure fewer than 10 optimised points (also held fixed)
  int keyframes = 0;
  /// [-] `ba_fixed_keyframes`, the oldest window keyframes held fixed (keyframes held for too
  /// few points are counted in `keyframes`, not here)
  int fixed_keyframes = 0;
  int points = 0;        ///< [-] map points optimised
  int measurements = 0;  ///< [-] RGB-D measurements (residuals) in the first round
  int outliers = 0;      ///< [-] measurements left out by the final chi-square test
  int iterations = 0;    ///< [-] solver iterations, both rounds
  double time_ms = 0.0;  ///< [ms] wall time
  /// [m], [deg] largest move of a keyframe's camera centre and rotation from the front end's pose
  double largest_correction_m = 0.0, largest_correction_deg = 0.0;
  /// [-] largest squared Mahalanobis size of a correction under the front end's pose information
  double largest_correction_chi2 = 0.0;
  /// The solution moved a keyframe further than `ba_max_correction_chi2` (under its front-end
  /// pose information), `ba_max_correction_m` or `ba_max_correction_deg` allow: not applied.
  bool rejected = false;
};

/// What one back-end static point determination did; counts and times of the paper's Table 7.
struct WindowStaticPointsStats {
  bool ran = false;       ///< false: too few keyframes or points (nothing changed)
  int keyframes = 0;      ///< [-] covisible window keyframes whose measurements were used
  int unmarked = 0;       ///< [-] points that lost their mark
  double total_ms = 0.0;  ///< [ms] everything, collecting the input included
  /// The DetermineStaticPoints call on the window's marked points (graph vertices), its edges,
  /// measurements z_ijk, culled edges and step times; all zero when it did not run.
  StaticPointsStats graph;
};

/// What the back end did after a keyframe (see dslam/backend/slam.h); all zero otherwise.
struct BackEndStatus {
  int window_keyframes = 0;     ///< [-] keyframes in the window
  WindowStaticPointsStats spd;  ///< static point determination over the window, before local BA
  LocalBaStats ba;              ///< local bundle adjustment; ba.ran: it ran after this frame
};

}  // namespace dslam
