#pragma once
// Moving objects tracked across frames: the dynamic mask's regions (dynamic_mask.h) become
// observations; each is associated with a track by predicted position and colour (greedy, lowest
// cost first, gated), and each track filters its centroid with a constant-velocity Kalman filter.
// A track is reported from its ObjectsConfig::min_hits-th observation on, in the frames where it
// is observed, and dropped after ObjectsConfig::max_unseen_s without an observation. Positions,
// velocities and extents are in the odometry (world) frame of the poses given.

#include <vector>

#include <Eigen/Core>

#include "dslam/core/objects_config.h"
#include "dslam/mapping/dynamic_mask.h"

namespace dslam {

/// One moving thing seen in one frame.
struct ObjectObservation {
  Eigen::Vector3d centroid_world = Eigen::Vector3d::Zero();  ///< [m] world frame
  Eigen::Vector3d extent = Eigen::Vector3d::Zero();  ///< [m] full size of its box (world axes)
  Eigen::Vector3d colour = Eigen::Vector3d::Zero();  ///< [0, 1] mean colour (B, G, R)
  int points = 0;                                    ///< unmarked points it holds
};

/// A tracked moving object as reported for one frame.
struct TrackedObject {
  int id = 0;                                                ///< stable across frames, from 1
  Eigen::Vector3d position_world = Eigen::Vector3d::Zero();  ///< [m] filtered centroid
  Eigen::Vector3d velocity_world = Eigen::Vector3d::Zero();  ///< [m/s] filtered velocity
  Eigen::Vector3d extent = Eigen::Vector3d::Zero();  ///< [m] full size (world axes), last seen
  int points = 0;                                    ///< unmarked points at the last observation
  double age_s = 0.0;                                ///< [s] since the track's first observation
};

/// The observations of one frame: the mask's regions with at least ObjectsConfig::min_points
/// points and min_cells cells.
std::vector<ObjectObservation> ObservationsFromMask(const DynamicMask& mask,
                                                    const ObjectsConfig& config);

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
    int hits = 0;
  };

  void Predict(Track* track, double dt_s) const;
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
