#include "dslam/eval/trajectory_metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dslam/eval/quantile.h"
#include "dslam/io/stamp_association.h"

namespace dslam {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

const StampedPose& NearestPose(const Trajectory& poses, double stamp_s, double max_dt_s) {
  const StampedPose* best = nullptr;
  for (const StampedPose& pose : poses) {
    if (!best || std::abs(pose.stamp_s - stamp_s) < std::abs(best->stamp_s - stamp_s)) {
      best = &pose;
    }
  }
  if (!best || std::abs(best->stamp_s - stamp_s) > max_dt_s) {
    throw std::runtime_error("no ground-truth pose within " + std::to_string(max_dt_s) +
                             " s of stamp " + std::to_string(stamp_s));
  }
  return *best;
}

double AngleOf(const Eigen::Matrix3d& rotation) {
  return Eigen::AngleAxisd(Eigen::Quaterniond(rotation).normalized()).angle();
}

}  // namespace

PoseAssociation AssociatePoses(const Trajectory& estimated, const Trajectory& groundtruth,
                               double max_dt_s) {
  std::vector<double> estimated_stamps, groundtruth_stamps;
  for (const StampedPose& p : estimated) estimated_stamps.push_back(p.stamp_s);
  for (const StampedPose& p : groundtruth) groundtruth_stamps.push_back(p.stamp_s);
  PoseAssociation association;
  for (const auto& [e, g] : AssociateStamps(estimated_stamps, groundtruth_stamps, max_dt_s)) {
    association.estimated.push_back(estimated[e]);
    association.groundtruth.push_back(groundtruth[g]);
  }
  return association;
}

Eigen::Isometry3d AlignPositions(const std::vector<Eigen::Vector3d>& source,
                                 const std::vector<Eigen::Vector3d>& target) {
  if (source.size() != target.size() || source.empty()) {
    throw std::invalid_argument("AlignPositions needs equally many points, at least one");
  }
  Eigen::Matrix3Xd src(3, source.size());
  Eigen::Matrix3Xd dst(3, target.size());
  for (size_t k = 0; k < source.size(); ++k) {
    src.col(k) = source[k];
    dst.col(k) = target[k];
  }
  // Umeyama's closed form without scale: R = U diag(1, 1, +-1) V^T of the cross-covariance,
  // t = mean(target) - R mean(source).
  const Eigen::Matrix4d T = Eigen::umeyama(src, dst, /*with_scaling=*/false);
  Eigen::Isometry3d T_target_source = Eigen::Isometry3d::Identity();
  T_target_source.linear() = T.topLeftCorner<3, 3>();
  T_target_source.translation() = T.topRightCorner<3, 1>();
  return T_target_source;
}

ErrorStatistics ComputeErrorStatistics(std::vector<double> errors) {
  ErrorStatistics stats;
  if (errors.empty()) return stats;
  std::sort(errors.begin(), errors.end());
  double sum = 0.0;
  double sum_squares = 0.0;
  for (double e : errors) {
    sum += e;
    sum_squares += e * e;
  }
  const size_t n = errors.size();
  stats.rmse = std::sqrt(sum_squares / n);
  stats.mean = sum / n;
  stats.median = Median(errors);
  stats.max = errors.back();
  return stats;
}

RelativePoseError ComputeRelativePoseError(const PoseAssociation& association,
                                           const TrajectoryMetricsOptions& options) {
  const Trajectory& P = association.estimated;
  const Trajectory& Q = association.groundtruth;
  std::vector<double> stamps;
  for (const StampedPose& pose : P) stamps.push_back(pose.stamp_s);
  double sum_trans_sq = 0.0;
  double sum_rot_sq = 0.0;
  RelativePoseError rpe;
  for (size_t i = 0; i < P.size(); ++i) {
    const auto it =
        std::lower_bound(stamps.begin() + i + 1, stamps.end(), stamps[i] + options.rpe_interval_s);
    if (it == stamps.end()) break;
    const double dt = *it - stamps[i];
    if (dt > options.rpe_interval_s + options.rpe_interval_tolerance_s || !(dt > 0.0)) continue;
    const size_t j = it - stamps.begin();
    const Eigen::Isometry3d Q_rel = Q[i].T_world_camera.inverse() * Q[j].T_world_camera;
    const Eigen::Isometry3d P_rel = P[i].T_world_camera.inverse() * P[j].T_world_camera;
    const Eigen::Isometry3d E = Q_rel.inverse() * P_rel;
    const double trans = E.translation().norm() / dt;
    const double rot = AngleOf(E.linear()) * kRadToDeg / dt;
    sum_trans_sq += trans * trans;
    sum_rot_sq += rot * rot;
    ++rpe.num_pairs;
  }
  if (rpe.num_pairs > 0) {
    rpe.translation_rmse_m_per_s = std::sqrt(sum_trans_sq / rpe.num_pairs);
    rpe.rotation_rmse_deg_per_s = std::sqrt(sum_rot_sq / rpe.num_pairs);
  }
  return rpe;
}

Coverage ComputeCoverage(const std::vector<double>& estimated_stamps_s, double span_start_s,
                         double span_end_s, double max_gap_s) {
  if (!(span_end_s > span_start_s)) {
    throw std::invalid_argument("coverage span must have positive length");
  }
  std::vector<double> points = {span_start_s, span_end_s};
  for (double t : estimated_stamps_s) {
    if (t >= span_start_s && t <= span_end_s) points.push_back(t);
  }
  std::sort(points.begin(), points.end());
  Coverage coverage;
  coverage.span_start_s = span_start_s;
  coverage.span_end_s = span_end_s;
  for (size_t k = 0; k + 1 < points.size(); ++k) {
    const double gap = points[k + 1] - points[k];
    if (gap <= max_gap_s) coverage.covered_s += gap;
  }
  coverage.fraction = std::min(1.0, coverage.covered_s / (span_end_s - span_start_s));
  return coverage;
}

FrameSteps ComputeFrameSteps(const PoseAssociation& association, double max_gap_s) {
  std::vector<double> steps, truth_steps;
  const Trajectory& est = association.estimated;
  const Trajectory& gt = association.groundtruth;
  for (size_t k = 1; k < est.size(); ++k) {
    if (est[k].stamp_s - est[k - 1].stamp_s > max_gap_s) continue;
    steps.push_back(
        (est[k].T_world_camera.translation() - est[k - 1].T_world_camera.translation()).norm());
    truth_steps.push_back(
        (gt[k].T_world_camera.translation() - gt[k - 1].T_world_camera.translation()).norm());
  }
  FrameSteps result;
  result.num_steps = steps.size();
  result.step_m = ComputeErrorStatistics(std::move(steps));
  result.truth_step_m = ComputeErrorStatistics(std::move(truth_steps));
  return result;
}

TrajectoryMetrics EvaluateTrajectory(const Trajectory& estimated, const Trajectory& groundtruth,
                                     const std::vector<double>& frame_stamps_s,
                                     const TrajectoryMetricsOptions& options) {
  TrajectoryMetrics metrics;
  metrics.num_estimated = estimated.size();
  metrics.num_groundtruth = groundtruth.size();
  metrics.association = AssociatePoses(estimated, groundtruth, options.max_association_dt_s);
  const PoseAssociation& association = metrics.association;
  metrics.num_associated = association.estimated.size();
  if (metrics.num_associated == 0) {
    throw std::runtime_error("no estimated pose has a ground-truth pose within " +
                             std::to_string(options.max_association_dt_s) + " s");
  }
  std::vector<Eigen::Vector3d> est_positions, gt_positions;
  for (size_t k = 0; k < metrics.num_associated; ++k) {
    est_positions.push_back(association.estimated[k].T_world_camera.translation());
    gt_positions.push_back(association.groundtruth[k].T_world_camera.translation());
  }
  metrics.T_gtworld_estworld = AlignPositions(est_positions, gt_positions);
  std::vector<double> ate_errors;
  for (size_t k = 0; k < metrics.num_associated; ++k) {
    ate_errors.push_back((gt_positions[k] - metrics.T_gtworld_estworld * est_positions[k]).norm());
  }
  metrics.ate_m = ComputeErrorStatistics(std::move(ate_errors));
  metrics.rpe = ComputeRelativePoseError(association, options);
  metrics.steps = ComputeFrameSteps(association, options.max_gap_s);

  const auto by_stamp = [](const StampedPose& a, const StampedPose& b) {
    return a.stamp_s < b.stamp_s;
  };
  double start = std::min_element(groundtruth.begin(), groundtruth.end(), by_stamp)->stamp_s;
  double end = std::max_element(groundtruth.begin(), groundtruth.end(), by_stamp)->stamp_s;
  if (!frame_stamps_s.empty()) {
    start = std::max(start, *std::min_element(frame_stamps_s.begin(), frame_stamps_s.end()));
    end = std::min(end, *std::max_element(frame_stamps_s.begin(), frame_stamps_s.end()));
  }
  if (!(end > start)) {
    throw std::runtime_error("the frames' time span does not overlap the ground truth's");
  }
  std::vector<double> estimated_stamps;
  for (const StampedPose& pose : estimated) estimated_stamps.push_back(pose.stamp_s);
  metrics.coverage = ComputeCoverage(estimated_stamps, start, end, options.max_gap_s);
  return metrics;
}

Eigen::Isometry3d EstimateFrameInWorld(const Trajectory& groundtruth, double first_frame_stamp_s,
                                       const Trajectory& estimated, double max_dt_s) {
  if (estimated.empty()) {
    return NearestPose(groundtruth, first_frame_stamp_s, max_dt_s).T_world_camera;
  }
  const StampedPose* first = &estimated.front();
  for (const StampedPose& pose : estimated) {
    if (pose.stamp_s < first->stamp_s) first = &pose;
  }
  return NearestPose(groundtruth, first->stamp_s, max_dt_s).T_world_camera *
         first->T_world_camera.inverse();
}

}  // namespace dslam
