#pragma once
// Moving-object tracking against synthetic truth (objects.txt of dslam_synth). Estimates are moved
// into the ground truth's world by T_world_estworld (the first frame's ground-truth pose when the
// estimate's frame is the first frame's optical frame) and assigned to the frame of the nearest
// ground-truth stamp. Per frame, estimates are matched one to one to the truth objects of the
// frame by GatedAssignment (assignment.h) on the centroid distance. Evaluated truth
// object-frames are those within max_range_m of the camera (ground-truth position at the frame)
// and covering at least min_pixel_share of the image. Scores:
// - found share: evaluated truth object-frames matched / evaluated truth object-frames;
// - centroid and velocity errors: |p_est - p_true|, |v_est - v_true| over those matches;
// - false share: estimates matched to no truth object / (estimates - estimates matched to truth
//   objects outside the filter): an estimate of an object that is too far or too small is
//   neither true nor false;
// - id switches (CLEAR-MOT, Bernardin and Stiefelhagen 2008): evaluated matches whose estimate id
//   differs from the estimate id of the same truth object's previous evaluated match;
// - MOTA = 1 - (misses + false objects + id switches) / evaluated truth object-frames.

#include <map>
#include <vector>

#include <Eigen/Geometry>

#include "dslam/core/trajectory.h"
#include "dslam/eval/object_files.h"

namespace dslam {

/// Parameters of EvaluateObjects().
struct ObjectMetricsOptions {
  double gate_m = 0.5;       ///< [m] largest centroid distance of a match
  double max_range_m = 4.0;  ///< [m] evaluated truth objects are at most this far from the camera
  double min_pixel_share = 0.02;  ///< [-] evaluated truth objects cover at least this share
  double max_dt_s = 0.005;        ///< [s] largest |stamp - ground-truth stamp| of a line's frame
};

/// The counts and scores of EvaluateObjects(). found_share, the medians and MOTA are NaN without
/// evaluated truth object-frames (or matches); false_share is 0 without scored estimates.
struct ObjectMetrics {
  long frames = 0;                   ///< ground-truth frames
  long truth_object_frames = 0;      ///< evaluated truth object-frames (range and share filter)
  long found = 0;                    ///< of those, matched to an estimate
  long estimated_object_frames = 0;  ///< estimate lines assigned to a frame
  long ignored_estimates = 0;        ///< matched to a truth object outside the filter
  long false_objects = 0;            ///< matched to no truth object
  long unassociated_estimates = 0;   ///< no ground-truth stamp within max_dt_s (not scored)
  long unassociated_truth = 0;       ///< truth lines without a ground-truth stamp (not scored)
  long id_switches = 0;              ///< CLEAR-MOT identity switches over evaluated matches
  std::vector<double> centroid_errors_m;    ///< [m] per evaluated match
  std::vector<double> velocity_errors_mps;  ///< [m/s] per evaluated match
  double found_share = 0.0;                 ///< found / truth_object_frames
  double false_share = 0.0;  ///< false_objects / (estimated_object_frames - ignored_estimates)
  double centroid_error_median_m = 0.0;    ///< [m] median of centroid_errors_m
  double velocity_error_median_mps = 0.0;  ///< [m/s] median of velocity_errors_mps
  double mota = 0.0;  ///< 1 - (misses + false_objects + id_switches) / truth_object_frames
};

/// Measures `estimated` (estimate's frame) against `truth` (world frame); `groundtruth` gives the
/// frames (stamps) and the camera positions (T_world_camera) used by the range filter.
ObjectMetrics EvaluateObjects(const std::vector<TruthObject>& truth,
                              const std::vector<EstimatedObject>& estimated,
                              const Trajectory& groundtruth,
                              const Eigen::Isometry3d& T_world_estworld,
                              const ObjectMetricsOptions& options);

/// The objects of one frame, both in the world frame.
struct FrameObjects {
  Eigen::Vector3d camera_position_m = Eigen::Vector3d::Zero();  ///< [m] world frame
  std::vector<TruthObject> truth;
  std::vector<EstimatedObject> estimated;
};

/// Scores one frame into `metrics` (counts and error lists, not the shares); `last_match` maps a
/// truth id to the estimate id of its previous evaluated match and is updated.
void ScoreFrame(const FrameObjects& frame, const ObjectMetricsOptions& options,
                std::map<int, int>* last_match, ObjectMetrics* metrics);

/// Fills the shares, medians and MOTA of `metrics` from its counts and error lists.
void FinishObjectMetrics(ObjectMetrics* metrics);

}  // namespace dslam
