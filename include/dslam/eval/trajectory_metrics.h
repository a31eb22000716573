#pragma once
// Trajectory accuracy after the TUM RGB-D benchmark (Sturm et al., IROS 2012): association by
// timestamp, closed-form SE(3) alignment (Umeyama 1991 without scale), absolute trajectory error
// (ATE), relative pose error (RPE) over fixed time intervals, and the share of the sequence that
// the estimate covers. All poses are T_world_camera; the estimate and the ground truth may use
// different world frames (ATE aligns them, RPE does not need to).

#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/io/trajectory_io.h"

namespace dslam {

/// Parameters of EvaluateTrajectory().
struct TrajectoryMetricsOptions {
  double max_association_dt_s = 0.02;     ///< [s] max |stamp_est - stamp_gt| of an associated pair
  double rpe_interval_s = 1.0;            ///< [s] nominal time between the two poses of an RPE pair
  double rpe_interval_tolerance_s = 0.1;  ///< [s] max excess of a pair's interval over the nominal
  double max_gap_s = 0.1;  ///< [s] longest gap between estimates that still counts as covered
};

/// Estimated and ground-truth poses matched one to one, in increasing estimated stamp.
struct PoseAssociation {
  Trajectory estimated;    ///< estimated poses (T_world_camera in the estimate's world)
  Trajectory groundtruth;  ///< the matched ground-truth poses (same size and order)
};

/// Associates estimated poses with ground-truth poses by stamp, as TUM's associate.py: every pair
/// with |dt| <= max_dt_s is a candidate, candidates are taken greedily by increasing |dt|, and
/// each estimated and each ground-truth pose is used at most once. Result sorted by estimated
/// stamp. Inputs need not be sorted.
PoseAssociation AssociatePoses(const Trajectory& estimated, const Trajectory& groundtruth,
                               double max_dt_s);

/// Closed-form rigid alignment without scale (Umeyama 1991, Horn 1987): the T_target_source that
/// minimises sum_k |target_k - T * source_k|^2. Needs equally many points, at least one; with
/// fewer than three non-collinear points the rotation is one of several minimisers.
/// Throws std::invalid_argument on a size mismatch or empty input.
Eigen::Isometry3d AlignPositions(const std::vector<Eigen::Vector3d>& source,
                                 const std::vector<Eigen::Vector3d>& target);

/// Summary statistics of non-negative errors.
struct ErrorStatistics {
  double rmse = 0.0;    ///< sqrt(mean(e^2))
  double mean = 0.0;    ///< mean(e)
  double median = 0.0;  ///< Median(e) (quantile.h: halfway between the middle two of an even count)
  double max = 0.0;     ///< max(e)
};

/// Statistics of `errors`; all zero for an empty input.
ErrorStatistics ComputeErrorStatistics(std::vector<double> errors);

/// Relative pose error over fixed time intervals (TUM). For each associated index i, j is the
/// first index with stamp_j >= stamp_i + rpe_interval_s (estimated stamps); the pair is used when
/// stamp_j - stamp_i <= rpe_interval_s + rpe_interval_tolerance_s. With Q ground truth and P the
/// estimate, E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j); the translational error is |t(E)| and the
/// rotational error the angle of R(E), each divided by the pair's actual interval stamp_j -
/// stamp_i.
struct RelativePoseError {
  size_t num_pairs = 0;                   ///< pairs used
  double translation_rmse_m_per_s = 0.0;  ///< [m/s] RMSE of |t(E)| / dt (0 when no pairs)
  double rotation_rmse_deg_per_s = 0.0;   ///< [deg/s] RMSE of angle(R(E)) / dt (0 when no pairs)
};

/// RPE of an association (see RelativePoseError).
RelativePoseError ComputeRelativePoseError(const PoseAssociation& association,
                                           const TrajectoryMetricsOptions& options);

/// How far the camera centre moves between consecutive associated poses (pairs at most
/// max_gap_s apart), in the estimate and in the ground truth: frame-to-frame jitter and jumps that
/// ATE, after its alignment, hides.
struct FrameSteps {
  size_t num_steps = 0;          ///< consecutive pairs used
  ErrorStatistics step_m;        ///< [m] |c_est(k+1) - c_est(k)|
  ErrorStatistics truth_step_m;  ///< [m] |c_gt(k+1) - c_gt(k)|
};

/// FrameSteps of an association; pairs further apart in time than `max_gap_s` [s] are skipped.
FrameSteps ComputeFrameSteps(const PoseAssociation& association, double max_gap_s);

/// Time coverage of a sequence by estimated poses.
struct Coverage {
  double span_start_s = 0.0;  ///< [s] start of the evaluated span
  double span_end_s = 0.0;    ///< [s] end of the evaluated span
  double covered_s = 0.0;     ///< [s] covered length
  double fraction = 0.0;      ///< covered_s / (span_end_s - span_start_s), in [0, 1]
};

/// Coverage of [span_start_s, span_end_s] by estimated stamps. Only estimated stamps inside the
/// span are considered; with them sorted, t_1 <= ... <= t_n, the points
/// span_start_s, t_1, ..., t_n, span_end_s cut the span into consecutive intervals, and an interval
/// counts as covered when its length is <= max_gap_s, else as uncovered as a whole. So the start
/// (end) of the span is covered up to the first (from the last) estimate only if that distance is
/// <= max_gap_s, and with no estimate in the span the coverage is 0 (unless the span itself is
/// <= max_gap_s). Throws std::invalid_argument when span_end_s <= span_start_s.
Coverage ComputeCoverage(const std::vector<double>& estimated_stamps_s, double span_start_s,
                         double span_end_s, double max_gap_s);

/// Everything EvaluateTrajectory() measures.
struct TrajectoryMetrics {
  size_t num_estimated = 0;     ///< poses in the estimate
  size_t num_groundtruth = 0;   ///< poses in the ground truth
  size_t num_associated = 0;    ///< associated pairs (ATE and RPE use only these)
  PoseAssociation association;  ///< the pairs (AssociatePoses() with max_association_dt_s)
  Eigen::Isometry3d T_gtworld_estworld = Eigen::Isometry3d::Identity();  ///< ATE alignment
  ErrorStatistics ate_m;  ///< [m] |p_gt - T_gtworld_estworld * p_est| over associated pairs
  RelativePoseError rpe;  ///< see RelativePoseError
  FrameSteps steps;       ///< see FrameSteps (pairs at most max_gap_s apart)
  Coverage coverage;      ///< see ComputeCoverage()
};

/// Associates, aligns and measures `estimated` against `groundtruth`. The coverage span is the
/// span of `frame_stamps_s` (the input frames, e.g. rgb.txt) clipped to the ground truth's span,
/// or the ground truth's span when `frame_stamps_s` is empty; all estimated stamps count for
/// coverage. Throws std::runtime_error when nothing associates or the span is empty.
TrajectoryMetrics EvaluateTrajectory(const Trajectory& estimated, const Trajectory& groundtruth,
                                     const std::vector<double>& frame_stamps_s,
                                     const TrajectoryMetricsOptions& options);

/// Where the frame of dslam_run_dataset's outputs (trajectory, map, objects: the first frame's
/// optical frame) lies in the ground truth's world, for measurements that compare those outputs
/// with world-frame truth without aligning them (object_metrics.h, map_metrics.h).
/// T_world_estworld: with an estimated trajectory, T_world_camera(gt, t0) *
/// T_estworld_camera(t0)^-1 at the stamp t0 of its first pose (so an estimate whose first pose is
/// not the identity, e.g. when tracking began after the first frame, is placed right); without one
/// (empty), the ground-truth pose nearest to `first_frame_stamp_s` [s]. The ground-truth pose must
/// lie within `max_dt_s` [s] of the stamp, else std::runtime_error.
Eigen::Isometry3d EstimateFrameInWorld(const Trajectory& groundtruth, double first_frame_stamp_s,
                                       const Trajectory& estimated, double max_dt_s);

}  // namespace dslam
