#include "dslam/eval/loop_check.h"

#include <algorithm>
#include <cmath>

#include "dslam/core/geometry.h"

namespace dslam {

bool InterpolatePose(const Trajectory& groundtruth, double stamp_s, double max_gap_s,
                     Eigen::Isometry3d* T_world_camera) {
  const auto after =
      std::lower_bound(groundtruth.begin(), groundtruth.end(), stamp_s,
                       [](const StampedPose& pose, double stamp) { return pose.stamp_s < stamp; });
  if (after == groundtruth.end()) return false;
  if (after->stamp_s == stamp_s) {
    *T_world_camera = after->T_world_camera;
    return true;
  }
  if (after == groundtruth.begin()) return false;
  const StampedPose& a = *(after - 1);
  const StampedPose& b = *after;
  if (b.stamp_s - a.stamp_s > max_gap_s) return false;
  const double f = (stamp_s - a.stamp_s) / (b.stamp_s - a.stamp_s);
  const Eigen::Quaterniond qa(a.T_world_camera.rotation()), qb(b.T_world_camera.rotation());
  T_world_camera->setIdentity();
  T_world_camera->linear() = qa.slerp(f, qb).toRotationMatrix();
  T_world_camera->translation() =
      (1.0 - f) * a.T_world_camera.translation() + f * b.T_world_camera.translation();
  return true;
}

LoopCheck CheckLoops(const std::vector<LoopRecord>& loops, const Trajectory& groundtruth,
                     const LoopCheckOptions& options) {
  LoopCheck check;
  for (const LoopRecord& loop : loops) {
    LoopVerdict verdict;
    verdict.loop = loop;
    Eigen::Isometry3d T_world_query, T_world_match;
    verdict.checked = InterpolatePose(groundtruth, loop.stamp_query_s,
                                      options.max_groundtruth_gap_s, &T_world_query) &&
                      InterpolatePose(groundtruth, loop.stamp_match_s,
                                      options.max_groundtruth_gap_s, &T_world_match);
    if (verdict.checked) {
      const Eigen::Isometry3d T_match_query_true = T_world_match.inverse() * T_world_query;
      const Eigen::Isometry3d error = T_match_query_true.inverse() * loop.T_match_query;
      verdict.translation_error_m = error.translation().norm();
      verdict.rotation_error_deg = RotationAngleDeg(error.rotation());
      verdict.true_distance_m = T_match_query_true.translation().norm();
      verdict.false_loop = verdict.translation_error_m > options.max_translation_m ||
                           verdict.rotation_error_deg > options.max_rotation_deg;
      ++check.checked;
      check.false_loops += verdict.false_loop;
      check.max_translation_error_m =
          std::max(check.max_translation_error_m, verdict.translation_error_m);
      check.max_rotation_error_deg =
          std::max(check.max_rotation_error_deg, verdict.rotation_error_deg);
    }
    check.verdicts.push_back(verdict);
  }
  return check;
}

}  // namespace dslam
