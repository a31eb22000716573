#pragma once
// What the back end reports after a keyframe: the stats each of its stages returns (local bundle
// adjustment, backend/local_bundle_adjustment.h; static point determination over the window,
// backend/window_static_points.h) and BackEndStatus, which embeds them. Plain structs here, in
// tracking, so that FrameResult (frame_result.h) carries them without the back end's headers.
// BackEndStatus::Fields() is the one table of the reported fields: the status CSV columns, the
// summary quantiles, their docs (eval/status_table.h) and the back-end fields of
// msg/FrameStatus.msg (checked by test/eval/status_table_test.cpp) follow it.

#include "dslam/core/status_field.h"
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
  /// [-] sum of all measurements' squared whitened residuals at the solution over the degrees of
  /// freedom (3 x measurements - 3 x points - 6 x free keyframes): about 1 when the noise model
  /// fits the measurements and nothing moved
  double chi2_per_dof = 0.0;
  /// [-] the same over the final chi-square test's inliers alone (their count, the points and
  /// free keyframes they measure): the fit of the bulk, without mismatches and moved points
  double inlier_chi2_per_dof = 0.0;
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

  /// The reported fields, each visited as v(StatusFieldInfo, value) in the order of the status
  /// CSV columns and of FrameStatus.msg; a field's summary_rank orders the summary's quantile
  /// keys. A new field is one entry here (and, for the message, a line in msg/FrameStatus.msg and
  /// one in FillBackEndStatus, ros/frame_publisher.cpp; test_eval and test_ros check both).
  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    constexpr StatusStage kBa = StatusStage::kLocalBa, kSpd = StatusStage::kWindowSpd;
    constexpr unsigned kCsv = kStatusCsv, kMsg = kStatusMessage, kBoth = kCsv | kMsg;
    v(StatusField("backend_ran", "-", kBa, kMsg, -1, "ran after this frame"), s.ba.ran);
    v(StatusField("ba_rejected", "-", kBa, kMsg, -1,
                  "its solution moved a keyframe too far and was not applied"),
      s.ba.rejected);
    v(StatusField("window_keyframes", "-", StatusStage::kWindow, kBoth, -1,
                  "keyframes in the window"),
      s.window_keyframes);
    v(StatusField("ba_keyframes", "-", kBa, 0, 1, "keyframes whose poses it optimised"),
      s.ba.keyframes);
    v(StatusField("ba_points", "-", kBa, kBoth, 2, "map points optimised"), s.ba.points);
    v(StatusField("ba_measurements", "-", kBa, kCsv, -1, "RGB-D measurements (residuals) it used"),
      s.ba.measurements);
    v(StatusField("ba_outliers", "-", kBa, kBoth, 3, "measurements the chi-square test left out"),
      s.ba.outliers);
    v(StatusField("ba_iterations", "-", kBa, kBoth, 4, "solver iterations"), s.ba.iterations);
    v(StatusField("ba_chi2_per_dof", "-", kBa, kCsv, 13,
                  "squared whitened residuals over the degrees of freedom (1: the noise fits)"),
      s.ba.chi2_per_dof);
    v(StatusField("ba_inlier_chi2_per_dof", "-", kBa, kCsv, 14,
                  "the same over the chi-square test's inliers alone"),
      s.ba.inlier_chi2_per_dof);
    v(StatusField("ba_ms", "ms", kBa, kBoth, 0, "its wall-clock time"), s.ba.time_ms);
    v(StatusField("spd_ran", "-", kSpd, kMsg, -1, "ran after this frame"), s.spd.ran);
    v(StatusField("spd_keyframes", "-", kSpd, 0, -1,
                  "covisible window keyframes whose measurements it used"),
      s.spd.keyframes);
    v(StatusField("spd_points", "-", kSpd, kBoth, 9, "marked points checked"), s.spd.graph.points);
    v(StatusField("spd_edges", "-", kSpd, 0, 10, "graph edges"), s.spd.graph.edges);
    v(StatusField("spd_culled_edges", "-", kSpd, kBoth, 11, "graph edges found inconsistent"),
      s.spd.graph.culled_edges);
    v(StatusField("spd_unmarked", "-", kSpd, kBoth, 12, "points that lost their mark"),
      s.spd.unmarked);
    v(StatusField("spd_graph_ms", "ms", kSpd, 0, 6, "Delaunay graph"), s.spd.graph.graph_ms);
    v(StatusField("spd_culling_ms", "ms", kSpd, 0, 7, "edge tests"), s.spd.graph.culling_ms);
    v(StatusField("spd_components_ms", "ms", kSpd, 0, 8, "components and labels"),
      s.spd.graph.components_ms);
    v(StatusField("spd_ms", "ms", kSpd, kBoth, 5, "its whole wall-clock time"), s.spd.total_ms);
  }
};

}  // namespace dslam
