#include "dslam/backend/local_bundle_adjustment.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <ceres/ceres.h>

#include "dslam/core/geometry.h"
#include "dslam/core/stopwatch.h"
#include "local_ba_problem.h"

namespace dslam {
namespace {

// Fewer window keyframes: no local BA.
constexpr int kMinKeyFrames = 2;
// Points measured in fewer window keyframes are not optimised. 3 was tried and not adopted: Bonn
// 51.1 -> 62.4 mm (docs/benchmarks/backend.md, "Back end on or off, seeds 1-5 and `walking`
// over 20 seeds").
constexpr int kMinPointKeyFrames = 2;
// Keyframes with fewer optimised points keep their pose.
constexpr int kMinKeyFramePoints = 10;
// Levenberg-Marquardt iterations per round.
constexpr int kMaxIterations = 10;

using local_ba::KeyFrameDepthResidual;
using local_ba::KeyFramePose;
using local_ba::Measurement;
using local_ba::Window;

// Verified static points measured in at least `min_keyframes` window keyframes, and the
// measurements of them, in keyframe order (deterministic).
Window CollectWindow(const Map& map, int min_keyframes) {
  Window window;
  std::unordered_map<PointId, int> seen_in;
  for (const KeyFrame& keyframe : map.window()) {
    for (const auto& [id, m] : keyframe.measurements.by_point) {
      const MapPoint* point = map.Find(id);
      if (point != nullptr && point->IsVerifiedStatic()) ++seen_in[id];
    }
  }
  for (size_t k = 0; k < map.window().size(); ++k) {
    const KeyFrame& keyframe = map.window()[k];
    const Eigen::Isometry3d& T = keyframe.measurements.T_camera_world;
    window.poses.push_back({Eigen::Quaterniond(T.rotation()), T.translation()});
    window.frozen_pose.push_back(map.IsFrozenKeyFrame(keyframe.id));
    for (const auto& [id, m] : keyframe.measurements.by_point) {
      const auto it = seen_in.find(id);
      if (it == seen_in.end() || it->second < min_keyframes) continue;
      window.measurements.push_back({static_cast<int>(k), id, &m});
      window.points.emplace(id, map.Find(id)->p_world);
      if (map.IsFrozenPoint(id)) window.frozen_points.insert(id);
    }
  }
  return window;
}

// Per window keyframe: whether the solve over the measurements flagged in `use` optimises its
// pose: not among the oldest `fixed_keyframes`, not frozen (window.frozen_pose), and with at
// least kMinKeyFramePoints of them.
std::vector<bool> FreeKeyFrames(const Window& window, const std::vector<bool>& use,
                                int fixed_keyframes) {
  std::vector<int> per_keyframe(window.poses.size(), 0);
  for (size_t i = 0; i < window.measurements.size(); ++i) {
    if (use[i]) ++per_keyframe[window.measurements[i].keyframe];
  }
  std::vector<bool> free(window.poses.size());
  for (size_t k = 0; k < free.size(); ++k) {
    free[k] = static_cast<int>(k) >= fixed_keyframes && !window.frozen_pose[k] &&
              per_keyframe[k] >= kMinKeyFramePoints;
  }
  return free;
}

// One Levenberg-Marquardt run over the measurements flagged in `use`. Returns the iterations.
int SolveRound(const Config& full_config, const std::vector<bool>& use, Window* window) {
  const BackendConfig& config = full_config.backend;
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  ceres::HuberLoss huber(full_config.pose.huber_delta_depth);
  ceres::EigenQuaternionManifold quaternion_manifold;
  for (size_t i = 0; i < window->measurements.size(); ++i) {
    if (!use[i]) continue;
    const Measurement& m = window->measurements[i];
    KeyFramePose& pose = window->poses[m.keyframe];
    problem.AddResidualBlock(KeyFrameDepthResidual::Create(*m.value).release(), &huber,
                             pose.q_camera_world.coeffs().data(), pose.t_camera_world.data(),
                             window->points.at(m.point).data());
  }
  const std::vector<bool> free = FreeKeyFrames(*window, use, config.ba_fixed_keyframes);
  for (size_t k = 0; k < window->poses.size(); ++k) {
    double* q = window->poses[k].q_camera_world.coeffs().data();
    double* t = window->poses[k].t_camera_world.data();
    if (!problem.HasParameterBlock(q)) continue;
    problem.SetManifold(q, &quaternion_manifold);
    if (!free[k]) {
      problem.SetParameterBlockConstant(q);
      problem.SetParameterBlockConstant(t);
    }
  }
  for (PointId id : window->frozen_points) {
    double* p = window->points.at(id).data();
    if (problem.HasParameterBlock(p)) problem.SetParameterBlockConstant(p);
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_SCHUR;
  options.max_num_iterations = kMaxIterations;
  options.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  return static_cast<int>(summary.iterations.size());
}

// R_k p_i + t_k - y_ik of measurement `m` at the window's current poses and points (paper
// Eq. rgbd_yik before whitening) [m].
Eigen::Vector3d Residual(const Window& window, const Measurement& m) {
  const KeyFramePose& pose = window.poses[m.keyframe];
  return pose.q_camera_world * window.points.at(m.point) + pose.t_camera_world - m.value->y_camera;
}

// Flags the measurements whose squared Mahalanobis error e^T C^-1 e is at most `chi2`, with C the
// measurement's C_ik, plus R C_point R^T when `map` is given (the map point's own uncertainty).
// With the map: the measurements consistent with the front end's keyframe poses and map
// positions. A point that moved since it was mapped (a person who stood still long enough to be
// verified, then walked) fails that test in the keyframes that saw it elsewhere, so it cannot pull
// the keyframes towards its motion.
std::vector<bool> WithinChi2(const Window& window, double chi2, const Map* map = nullptr) {
  std::vector<bool> inliers(window.measurements.size());
  for (size_t i = 0; i < window.measurements.size(); ++i) {
    const Measurement& m = window.measurements[i];
    const KeyFramePose& pose = window.poses[m.keyframe];
    const Eigen::Vector3d e = Residual(window, m);
    Eigen::Matrix3d covariance = m.value->covariance;
    if (map != nullptr) {
      covariance +=
          RotatedCovariance(pose.q_camera_world.toRotationMatrix(), map->Find(m.point)->cov_world);
    }
    inliers[i] = e.dot(covariance.inverse() * e) <= chi2;
  }
  return inliers;
}

// The sum of squared whitened residuals e^T C_ik^-1 e of the measurements flagged in `counted`
// over their degrees of freedom: 3 per measurement, less 3 per point they measure and 6 per
// keyframe free in the solve over the `used` measurements (FreeKeyFrames). 0 when there are none.
double Chi2PerDegreeOfFreedom(const Window& window, const std::vector<bool>& counted,
                              const std::vector<bool>& used, int fixed_keyframes) {
  double chi2 = 0.0;
  int measurements = 0;
  std::unordered_map<PointId, int> points;
  for (size_t i = 0; i < window.measurements.size(); ++i) {
    if (!counted[i]) continue;
    const Measurement& m = window.measurements[i];
    const Eigen::Vector3d e = Residual(window, m);
    chi2 += e.dot(m.value->covariance.inverse() * e);
    ++measurements;
    ++points[m.point];
  }
  const std::vector<bool> free = FreeKeyFrames(window, used, fixed_keyframes);
  const int free_keyframes = static_cast<int>(std::count(free.begin(), free.end(), true));
  const int dof = 3 * measurements - 3 * static_cast<int>(points.size()) - 6 * free_keyframes;
  return dof > 0 ? chi2 / dof : 0.0;
}

// Points measured in the window but not optimised (candidates, unmarked points, points of one
// keyframe) move with the newest keyframe that measured them, p <- T_wc_new T_cw_old p, so that
// they stay where that keyframe saw them.
void CarryUnoptimisedPoints(const Window& window, const std::vector<Eigen::Isometry3d>& correction,
                            Map* map) {
  std::unordered_map<PointId, int> newest_keyframe;
  for (size_t k = 0; k < map->window().size(); ++k) {
    for (const auto& [id, m] : map->window()[k].measurements.by_point) {
      if (!window.points.count(id)) newest_keyframe[id] = static_cast<int>(k);
    }
  }
  for (const auto& [id, k] : newest_keyframe) {
    MapPoint* point = map->FindWritable(id);
    if (point != nullptr) point->p_world = correction[k] * point->p_world;
  }
}

// The optimised T_camera_world of keyframe k.
Eigen::Isometry3d OptimisedPose(const Window& window, size_t k) {
  Eigen::Isometry3d T_camera_world = Eigen::Isometry3d::Identity();
  T_camera_world.linear() = window.poses[k].q_camera_world.normalized().toRotationMatrix();
  T_camera_world.translation() = window.poses[k].t_camera_world;
  return T_camera_world;
}

// How far the solution moved the keyframes from the front end's estimates (the largest over the
// window of each measure).
struct CorrectionSize {
  double metres = 0.0;   // [m] camera centre
  double degrees = 0.0;  // [deg] rotation
  // [-] squared Mahalanobis size under the keyframe's front-end pose information (keyframes
  // without one are skipped): how many sigmas the back end moved a pose away from what its own
  // frame's measurements said.
  double chi2 = 0.0;
};

CorrectionSize LargestCorrection(const Window& window, const Map& map) {
  CorrectionSize largest;
  for (size_t k = 0; k < map.window().size(); ++k) {
    const KeyFrame& keyframe = map.window()[k];
    const Eigen::Isometry3d T_camera_world = OptimisedPose(window, k);
    const Eigen::Isometry3d T_world_camera = T_camera_world.inverse();
    const Eigen::Isometry3d& T_old = keyframe.T_world_camera;
    largest.metres =
        std::max(largest.metres, (T_world_camera.translation() - T_old.translation()).norm());
    largest.degrees = std::max(
        largest.degrees, RotationAngleDeg(T_world_camera.rotation() * T_old.rotation().transpose()));
    if (keyframe.information.isZero()) continue;
    const Eigen::Isometry3d& T_old_camera_world = keyframe.measurements.T_camera_world;
    const Eigen::AngleAxisd rotation_camera(T_camera_world.rotation() *
                                            T_old_camera_world.rotation().transpose());
    Eigen::Matrix<double, 6, 1> delta;
    delta << rotation_camera.angle() * rotation_camera.axis(),
        T_camera_world.translation() - T_old_camera_world.translation();
    largest.chi2 = std::max(largest.chi2, delta.dot(keyframe.information * delta));
  }
  return largest;
}

// Writes poses and points back (frozen ones stay bitwise as they were). Outlier measurements
// stay in their keyframes: they are the evidence with which static point determination finds
// points that moved.
void WriteBack(const Window& window, Map* map) {
  std::deque<KeyFrame>& keyframes = map->mutable_window();
  std::vector<Eigen::Isometry3d> correction(keyframes.size());  // T_wc_new T_cw_old
  for (size_t k = 0; k < keyframes.size(); ++k) {
    correction[k] = Eigen::Isometry3d::Identity();
    if (window.frozen_pose[k]) continue;
    const Eigen::Isometry3d T_camera_world = OptimisedPose(window, k);
    correction[k] = T_camera_world.inverse() * keyframes[k].measurements.T_camera_world;
    keyframes[k].measurements.T_camera_world = T_camera_world;
    keyframes[k].T_world_camera = T_camera_world.inverse();
  }
  for (const auto& [id, p_world] : window.points) {
    if (window.frozen_points.count(id) == 0) map->Find(id)->p_world = p_world;
  }
  CarryUnoptimisedPoints(window, correction, map);
}

}  // namespace

LocalBaStats LocalBundleAdjustment(const Config& full_config, Map* map) {
  const BackendConfig& config = full_config.backend;
  const double chi2 = full_config.pose.chi2_depth;
  Stopwatch clock;
  LocalBaStats stats;
  const int num_keyframes = static_cast<int>(map->window().size());
  if (num_keyframes < kMinKeyFrames || num_keyframes <= config.ba_fixed_keyframes) {
    return stats;
  }
  Window window = CollectWindow(*map, kMinPointKeyFrames);
  if (window.points.empty()) return stats;
  std::vector<bool> use = WithinChi2(window, chi2, map);
  stats.iterations = SolveRound(full_config, use, &window);
  use = WithinChi2(window, chi2);
  stats.iterations += SolveRound(full_config, use, &window);
  const std::vector<bool> inliers = WithinChi2(window, chi2);
  const std::vector<bool> all(window.measurements.size(), true);
  stats.chi2_per_dof = Chi2PerDegreeOfFreedom(window, all, use, config.ba_fixed_keyframes);
  stats.inlier_chi2_per_dof =
      Chi2PerDegreeOfFreedom(window, inliers, use, config.ba_fixed_keyframes);
  const CorrectionSize correction = LargestCorrection(window, *map);
  stats.largest_correction_m = correction.metres;
  stats.largest_correction_deg = correction.degrees;
  stats.largest_correction_chi2 = correction.chi2;
  stats.rejected = stats.largest_correction_chi2 > config.ba_max_correction_chi2 ||
                   stats.largest_correction_m > config.ba_max_correction_m ||
                   stats.largest_correction_deg > config.ba_max_correction_deg;
  if (!stats.rejected) WriteBack(window, map);

  stats.ran = true;
  stats.fixed_keyframes = config.ba_fixed_keyframes;
  stats.keyframes = num_keyframes - config.ba_fixed_keyframes;
  stats.points = static_cast<int>(window.points.size());
  stats.measurements = static_cast<int>(window.measurements.size());
  stats.outliers = static_cast<int>(std::count(inliers.begin(), inliers.end(), false));
  stats.time_ms = clock.ElapsedMs();
  return stats;
}

}  // namespace dslam
