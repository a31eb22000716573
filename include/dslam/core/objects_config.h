#pragma once
// Config sections `dynamic_mask` (per-pixel masks of the moving things, grown from the unmarked
// points over the depth image) and `objects` (moving objects tracked across frames). Members of
// the one Config tree (config.h).

#include "dslam/core/config_field.h"

namespace dslam {

/// Per-pixel dynamic mask (dslam/mapping/dynamic_mask.h): the frame's unmarked points are
/// clustered in 3D, and each cluster grows over the depth image across depth-continuous
/// neighbours, staying within a margin of the cluster's points. Units, ranges and meanings of the
/// fields are given in Fields() (printed by `dslam_config_doc`).
struct DynamicMaskConfig {
  int decimation = 4;
  double cluster_distance_m = 0.35;
  int min_cluster_points = 4;
  double depth_step_m = 0.03;
  double depth_step_ratio = 0.02;
  double margin_m = 0.25;
  double max_depth_m = 6.0;
  double depth_change_interval_s = 0.2;
  int depth_change_references = 3;
  double depth_change_margin_m = 0.1;
  double depth_change_sigma_factor = 3.0;
  int depth_change_min_cells = 40;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    // The mask is computed on every decimation-th pixel in both directions (4: 160x120 cells at
    // 640x480), a cell's depth being the depth at its centre pixel.
    v(Field("decimation", "px", 1, 16, "mask cell size (pixels per cell side)"), s.decimation);
    // Single-linkage clustering of the unmarked points: a person's points are closer than this to
    // a neighbour of the same person.
    v(Field("cluster_distance_m", "m", 0.01, 5.0,
            "unmarked points closer than this belong to the same moving thing"),
      s.cluster_distance_m);
    v(Field("min_cluster_points", "-", 1, 10000,
            "clusters with fewer unmarked points are left out (isolated mislabels)"),
      s.min_cluster_points);
    // Neighbouring cells are depth-continuous when their depths differ by at most
    // depth_step_m + depth_step_ratio * depth (noise and slant grow with depth).
    v(Field("depth_step_m", "m", 0.0, 1.0, "depth continuity: constant part"), s.depth_step_m);
    v(Field("depth_step_ratio", "-", 0.0, 1.0, "depth continuity: part proportional to depth"),
      s.depth_step_ratio);
    // Growth stops this far outside the axis-aligned box (optical frame) of the cluster's points:
    // a person's region does not run into the floor or a wall it touches beyond this margin.
    v(Field("margin_m", "m", 0.0, 5.0, "how far a region may grow beyond its points' box"),
      s.margin_m);
    v(Field("max_depth_m", "m", 0.1, 100.0, "cells farther than this are never masked"),
      s.max_depth_m);
    // Depth-change seeds (dslam/mapping/depth_change.h): cells clearly nearer than a recent
    // reference frame saw along their ray (depth_change_margin_m + depth_change_sigma_factor *
    // sigma_d(depth), sigma_d of depth_noise) mark something that was not there then; connected
    // groups of at least depth_change_min_cells such cells grow regions like the points' clusters.
    // Reference frames: one every depth_change_interval_s, the newest depth_change_references kept.
    // The cells on every 2nd row and column are tested (kDepthChangeStride, depth_change.h).
    v(Field("depth_change_interval_s", "s", 0.01, 10.0, "time between two reference frames"),
      s.depth_change_interval_s);
    v(Field("depth_change_references", "-", 1, 20, "reference frames kept (newest)"),
      s.depth_change_references);
    v(Field("depth_change_margin_m", "m", 0.0, 5.0,
            "constant part of the depth change a changed cell needs"),
      s.depth_change_margin_m);
    v(Field("depth_change_sigma_factor", "-", 0.0, 100.0,
            "depth-noise sigmas of the depth change a changed cell needs"),
      s.depth_change_sigma_factor);
    v(Field("depth_change_min_cells", "-", 1, 100000,
            "connected changed cells a depth-change seed needs"),
      s.depth_change_min_cells);
  }
};

/// Moving objects (dslam/mapping/object_tracker.h): each masked region with enough points is an
/// observation; observations are associated with tracks by position and colour and filtered with
/// a constant-velocity Kalman filter. Units, ranges and meanings of the fields are given in
/// Fields() (printed by `dslam_config_doc`).
struct ObjectsConfig {
  bool enabled = true;
  int min_points = 6;
  int track_min_points = 4;
  double gate_m = 0.6;
  double colour_weight_m = 0.3;
  double acceleration_sigma_mps2 = 3.0;
  double position_sigma_m = 0.08;
  double velocity_sigma_mps = 0.3;
  double velocity_baseline_s = 0.034;
  double motion_baseline_s = 0.25;
  double max_point_speed_mps = 4.0;
  double split_speed_mps = 0.5;
  double split_max_overlap = 0.5;
  double split_min_distance_m = 0.4;
  int min_hits = 2;
  double min_speed_mps = 0.2;
  double motion_sigma_factor = 3.0;
  double coast_s = 0.2;
  double max_unseen_s = 1.0;
  double maneuver_chi2 = 12.59;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    v(Flag("enabled", "detect and track moving objects"), s.enabled);
    v(Field("min_points", "-", 1, 10000, "unmarked points a region needs to become an observation"),
      s.min_points);
    // Where a tracked object is expected (its predicted position within gate_m), fewer unmarked
    // points suffice, both for a cluster (instead of dynamic_mask.min_cluster_points) and for an
    // observation (instead of min_points): the front end labels few points of a person at times.
    v(Field("track_min_points", "-", 1, 10000,
            "unmarked points a cluster or region near a tracked object needs"),
      s.track_min_points);
    // Association cost = predicted-position distance + colour_weight_m * colour distance (0..1);
    // pairs costing more than gate_m are never associated.
    v(Field("gate_m", "m", 0.01, 10.0, "largest association cost"), s.gate_m);
    v(Field("colour_weight_m", "m", 0.0, 10.0, "cost of a full colour mismatch"),
      s.colour_weight_m);
    v(Field("acceleration_sigma_mps2", "m/s^2", 0.01, 100.0,
            "constant-velocity filter: white acceleration noise"),
      s.acceleration_sigma_mps2);
    v(Field("position_sigma_m", "m", 0.001, 10.0, "noise of an observed centroid"),
      s.position_sigma_m);
    // An object's velocity is also measured directly: the per-axis median of its unmarked
    // points' displacements since the previous frame (the same point ids, re-measured in each
    // frame), when at least 3 points were seen in both.
    v(Field("velocity_sigma_mps", "m/s", 0.001, 100.0, "noise of an observed point velocity"),
      s.velocity_sigma_mps);
    // A walker turns or stops within a step, faster than the filter's acceleration noise
    // follows: when the normalised innovations of a track's last two observed point velocities
    // add up to more than maneuver_chi2 (chi-square, 6 dof; 12.59: 5 % of consistent pairs), the
    // track's velocity uncertainty is reset to a new track's before the second is applied: one
    // moderately inconsistent velocity (a few noisy points) alone does not reset it.
    v(Field("maneuver_chi2", "-", 0.0, 1e9,
            "two velocity innovations (chi-square, 6 dof) that reset the velocity uncertainty (0: "
            "never)"),
      s.maneuver_chi2);
    // Each point's velocity is taken from its oldest position within a baseline: the filter's
    // velocity measurement over velocity_baseline_s (short: it follows a walker's stops and
    // starts; 0.034 s = the previous frame at 30 Hz), whether a track moves at all over
    // motion_baseline_s (long: depth noise of static points averages out).
    v(Field("velocity_baseline_s", "s", 0.001, 2.0, "baseline of the filter's point velocity"),
      s.velocity_baseline_s);
    v(Field("motion_baseline_s", "s", 0.001, 2.0, "baseline of the point speed for min_speed_mps"),
      s.motion_baseline_s);
    // A faster point was matched to another thing's feature, e.g. a point of a person who left
    // re-matched on the wall behind: left out of the median. The same bound drops points carried
    // by optical flow (the points the front end lost, dslam/mapping/point_carrier.h).
    v(Field("max_point_speed_mps", "m/s", 0.01, 1000.0, "faster point velocities are outliers"),
      s.max_point_speed_mps);
    // A region whose points' velocities (over motion_baseline_s) form two groups (two-means)
    // whose per-axis medians differ by at least split_speed_mps, each group with at least
    // 5 points (kSplitMinPoints), is split in two (dslam/mapping/region_split.h): two people that
    // came close enough to be one cluster. A large split_speed_mps (e.g. 100) never splits.
    v(Field("split_speed_mps", "m/s", 0.01, 1000.0,
            "velocity difference of two groups of a region's points that splits it"),
      s.split_speed_mps);
    // The two parts the region's cells are shared into must also stand side by side in the
    // image: the overlap of their horizontal ranges (10th-90th percentile of the optical x of
    // their cells) at most this share of the narrower range.
    v(Field("split_max_overlap", "-", 0.0, 1.0,
            "largest horizontal overlap of two split parts (share of the narrower)"),
      s.split_max_overlap);
    // split_max_overlap also joins regions: regions one above the other in the image (column
    // ranges overlapping by more than it) whose world boxes come within dynamic_mask.margin_m are
    // the parts of one person whose seed points left a gap (dslam/mapping/region_join.h).
    // ... and their mean positions across the view (optical x and depth) at least
    // split_min_distance_m apart (two people side by side are a body's width apart; two halves
    // of one near person are not).
    v(Field("split_min_distance_m", "m", 0.0, 10.0,
            "smallest distance of the mean positions of two split parts across the view"),
      s.split_min_distance_m);
    // A track is reported once min_hits consecutive observations had a point velocity of at
    // least min_speed_mps: static surfaces mislabelled for a while are not objects. A walker that
    // stops stays reported (it moved before).
    v(Field("min_hits", "-", 1, 1000, "observations before a track is reported"), s.min_hits);
    v(Field("min_speed_mps", "m/s", 0.0, 100.0, "speed a track must reach to be reported"),
      s.min_speed_mps);
    // ... and at least motion_sigma_factor times the speed's standard deviation expected from
    // depth noise alone (features' depth_noise model at the region centroid's range, the points'
    // baselines and count): far static surfaces with a few mislabelled points have noisy speeds.
    v(Field("motion_sigma_factor", "-", 0.0, 100.0,
            "speed a track must reach, in depth-noise sigmas of its point speed (0: no test)"),
      s.motion_sigma_factor);
    // Short gaps (no observation: too few unmarked points in a frame) are bridged by the
    // filter's prediction.
    v(Field("coast_s", "s", 0.0, 60.0, "a reported track unseen for up to this is still reported"),
      s.coast_s);
    v(Field("max_unseen_s", "s", 0.0, 60.0, "a track unseen for longer is dropped"),
      s.max_unseen_s);
  }
};

}  // namespace dslam
