#pragma once
// Moving objects tracked across frames: the dynamic mask's regions (dynamic_mask.h) become
// observations; each is associated with a track by predicted position and colour (greedy, lowest
// cost first, gated), and each track filters its centroid (and its points' velocity) with a
// constant-velocity Kalman filter, whose velocity uncertainty is reset when two observed velocities
// in a row are inconsistent with it (a walker turning or stopping within a step). A track is
// reported once it moved (point speeds over motion_baseline_s of at least
// ObjectsConfig::min_speed_mps in min_hits consecutive observations: a static surface whose points
// were mislabelled never does), in the frames where it is observed and for coast_s after
// (predicted), and dropped after max_unseen_s unseen. Positions, velocities and extents are in the
// odometry (world) frame of the poses given.

#include <deque>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "dslam/core/features_config.h"
#include "dslam/core/objects_config.h"
#include "dslam/mapping/dynamic_mask.h"

namespace dslam {

/// One moving thing seen in one frame.
struct ObjectObservation {
  Eigen::Vector3d centroid_world = Eigen::Vector3d::Zero();  ///< [m] world frame
  Eigen::Vector3d extent = Eigen::Vector3d::Zero();  ///< [m] full size of its box (world axes)
  Eigen::Vector3d colour = Eigen::Vector3d::Zero();  ///< [0, 1] mean colour (B, G, R)
  int points = 0;                                    ///< unmarked points it holds
  /// [m/s] median (per axis) of its points' velocities, each from the point's oldest position
  /// in the recent frames (PointPositions history, at most ObjectsConfig::velocity_baseline_s old)
  /// to this one, world frame; valid when has_velocity (at least 3 points).
  Eigen::Vector3d velocity_world = Eigen::Vector3d::Zero();
  bool has_velocity = false;
  /// [m/s] speed of the same median over the longer ObjectsConfig::motion_baseline_s (whether
  /// it moves at all: depth noise averaged over more frames); 0 when not measured.
  double motion_speed_mps = 0.0;
  /// [m/s] standard deviation of motion_speed_mps expected from depth noise alone (the depth
  /// sigma at the centroid's range, the points' baselines and count); 0 when not known.
  double motion_sigma_mps = 0.0;
  /// Fewer than ObjectsConfig::min_points points (kept near a predicted track position): it
  /// updates a track but starts none, and a track seen only in such observations for longer than
  /// max_unseen_s is dropped.
  bool weak = false;
};

/// World positions of the unmarked points of one frame, by id: the recent frames' positions, from
/// which ObservationsFromMask measures the points' velocities.
struct PointPositions {
  double stamp_s = 0.0;                                ///< [s]
  std::unordered_map<PointId, Eigen::Vector3d> by_id;  ///< [m] world frame
};

/// The positions of the points seeding `mask`'s regions, stamped `stamp_s` [s].
PointPositions PositionsOf(const DynamicMask& mask, double stamp_s);

/// Velocity [m/s, world frame] of point `id` at `p_world` [m] at `stamp_s` [s], from its oldest
/// position in `history` (oldest first) at most `baseline_s` [s] old. False when no such position
/// exists or the speed exceeds ObjectsConfig::max_point_speed_mps (a match to another thing's
/// feature, not a motion).
bool PointVelocity(PointId id, const Eigen::Vector3d& p_world,
                   const std::deque<PointPositions>& history, double stamp_s, double baseline_s,
                   const ObjectsConfig& config, Eigen::Vector3d* velocity, double* dt_s = nullptr);

/// A tracked moving object as reported for one frame.
struct TrackedObject {
  int id = 0;                                                ///< stable across frames, from 1
  Eigen::Vector3d position_world = Eigen::Vector3d::Zero();  ///< [m] filtered centroid
  Eigen::Vector3d velocity_world = Eigen::Vector3d::Zero();  ///< [m/s] filtered velocity
  Eigen::Vector3d extent = Eigen::Vector3d::Zero();  ///< [m] full size (world axes), last seen
  int points = 0;                                    ///< unmarked points at the last observation
  double age_s = 0.0;                                ///< [s] since the track's first observation
};

/// The observations of one frame stamped `stamp_s` [s]: the mask's regions with at least
/// ObjectsConfig::min_points points and 20 cells; their velocities from `history` (the
/// recent frames' PositionsOf, oldest first; entries older than velocity_baseline_s are ignored).
/// Regions whose centroid lies within gate_m of one of `near_world` [m, world frame] (predicted
/// track positions) need only track_min_points points.
/// With `noise` (the depth noise model) and `camera_world` (the camera's position [m], world
/// frame), each observation's motion_sigma_mps is filled.
std::vector<ObjectObservation> ObservationsFromMask(
    const DynamicMask& mask, const ObjectsConfig& config, double stamp_s,
    const std::deque<PointPositions>& history, const DepthNoiseConfig* noise = nullptr,
    const Eigen::Vector3d& camera_world = Eigen::Vector3d::Zero(),
    const std::vector<Eigen::Vector3d>& near_world = {});

/// Tracks of moving objects over a sequence of frames (one thread).
class ObjectTracker {
 public:
  explicit ObjectTracker(const ObjectsConfig& config) : config_(config) {}

  /// Predicts the tracks to `stamp_s` [s], associates and applies `observations`, starts tracks
  /// for the unassociated ones, drops stale tracks; returns the reported objects of this frame.
  /// A stamp not after the previous one, or more than max_unseen_s after it, clears the tracks
  /// first (ids keep counting up).
  std::vector<TrackedObject> Update(double stamp_s,
                                    const std::vector<ObjectObservation>& observations);

  /// [m, world frame] positions at `stamp_s` [s] predicted by the constant-velocity filter of the
  /// tracks that moved (reported or coasting) and were seen within max_unseen_s; empty when
  /// Update(stamp_s, ...) would clear the tracks.
  std::vector<Eigen::Vector3d> PredictedPositions(double stamp_s) const;

  /// Forgets every track (ids keep counting up).
  void Reset() { tracks_.clear(); }

  int track_count() const { return static_cast<int>(tracks_.size()); }  ///< incl. unreported

 private:
  struct Track {
    int id = 0;
    Eigen::Matrix<double, 6, 1> x = Eigen::Matrix<double, 6, 1>::Zero();  ///< [p; v]
    Eigen::Matrix<double, 6, 6> P = Eigen::Matrix<double, 6, 6>::Identity();
    ObjectObservation last;
    double first_seen_s = 0.0, last_seen_s = 0.0;
    double last_full_s = 0.0;  ///< [s] last observation that was not weak
    int hits = 0;
    int moving_streak = 0;  ///< consecutive observations with a point velocity >= min_speed_mps
    bool moved = false;     ///< moving_streak reached min_hits once
    /// Normalised innovation (chi-square, 3 dof) of the last observed velocity; 0 before one and
    /// after a maneuver reset.
    double last_velocity_nis = 0.0;
  };

  void Predict(Track* track, double dt_s) const;
  /// Whether the observation's points moved: motion_speed_mps at least min_speed_mps and at
  /// least motion_sigma_factor times motion_sigma_mps.
  bool Moving(const ObjectObservation& observation) const;
  /// A maneuver (ObjectsConfig::maneuver_chi2): when the normalised innovations of this observed
  /// velocity and the track's previous one add up to more than maneuver_chi2, the track's
  /// velocity uncertainty becomes a new track's (cross terms cleared).
  void ResetOnManeuver(Track* track, const ObjectObservation& observation) const;
  void Correct(Track* track, const ObjectObservation& observation, double stamp_s) const;
  Track StartTrack(const ObjectObservation& observation, double stamp_s);
  /// Greedy association: for each observation, the index of its track or -1.
  std::vector<int> Associate(const std::vector<ObjectObservation>& observations) const;

  ObjectsConfig config_;
  std::vector<Track> tracks_;
  double last_stamp_s_ = 0.0;
  bool has_stamp_ = false;
  int next_id_ = 1;
};

}  // namespace dslam
