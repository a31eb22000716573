// Moving-object tracking against synthetic truth (object_metrics.h).
#include "dslam/eval/object_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dslam/eval/assignment.h"
#include "dslam/eval/quantile.h"

namespace dslam {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Index of the stamp in sorted `stamps` nearest to `t` if within max_dt, else -1.
int NearestFrame(const std::vector<double>& stamps, double t, double max_dt) {
  const long after = std::lower_bound(stamps.begin(), stamps.end(), t) - stamps.begin();
  int best = -1;
  double best_dt = max_dt;
  for (long k : {after - 1, after}) {
    if (k < 0 || k >= static_cast<long>(stamps.size())) continue;
    const double dt = std::abs(stamps[k] - t);
    if (dt <= best_dt) {
      best_dt = dt;
      best = static_cast<int>(k);
    }
  }
  return best;
}

double MedianOrNaN(const std::vector<double>& values) {
  return values.empty() ? kNaN : Median(values);
}

double ShareOrNaN(long count, long of) {
  return of > 0 ? static_cast<double>(count) / static_cast<double>(of) : kNaN;
}

}  // namespace

void ScoreFrame(const FrameObjects& frame, const ObjectMetricsOptions& options,
                std::map<int, int>* last_match, ObjectMetrics* m) {
  const size_t n_truth = frame.truth.size(), n_est = frame.estimated.size();
  std::vector<bool> evaluated(n_truth);
  for (size_t i = 0; i < n_truth; ++i) {
    const TruthObject& t = frame.truth[i];
    evaluated[i] = (t.position_m - frame.camera_position_m).norm() <= options.max_range_m &&
                   t.pixel_share >= options.min_pixel_share;
    m->truth_object_frames += evaluated[i] ? 1 : 0;
  }
  Eigen::MatrixXd distance(n_truth, n_est);
  for (size_t i = 0; i < n_truth; ++i) {
    for (size_t j = 0; j < n_est; ++j) {
      distance(i, j) = (frame.truth[i].position_m - frame.estimated[j].position_m).norm();
    }
  }
  m->estimated_object_frames += static_cast<long>(n_est);
  long matched = 0;
  for (const auto& [i, j] : GatedAssignment(distance, options.gate_m)) {
    ++matched;
    const TruthObject& t = frame.truth[i];
    const EstimatedObject& e = frame.estimated[j];
    if (!evaluated[i]) {
      ++m->ignored_estimates;
      continue;
    }
    ++m->found;
    m->centroid_errors_m.push_back(distance(i, j));
    m->velocity_errors_mps.push_back((e.velocity_mps - t.velocity_mps).norm());
    const auto previous = last_match->find(t.id);
    if (previous != last_match->end() && previous->second != e.id) ++m->id_switches;
    (*last_match)[t.id] = e.id;
  }
  m->false_objects += static_cast<long>(n_est) - matched;
}

void FinishObjectMetrics(ObjectMetrics* m) {
  m->found_share = ShareOrNaN(m->found, m->truth_object_frames);
  const long scored_estimates = m->estimated_object_frames - m->ignored_estimates;
  m->false_share = scored_estimates > 0 ? ShareOrNaN(m->false_objects, scored_estimates) : 0.0;
  m->centroid_error_median_m = MedianOrNaN(m->centroid_errors_m);
  m->velocity_error_median_mps = MedianOrNaN(m->velocity_errors_mps);
  const long misses = m->truth_object_frames - m->found;
  m->mota = m->truth_object_frames > 0
                ? 1.0 - static_cast<double>(misses + m->false_objects + m->id_switches) /
                            static_cast<double>(m->truth_object_frames)
                : kNaN;
}

ObjectMetrics EvaluateObjects(const std::vector<TruthObject>& truth,
                              const std::vector<EstimatedObject>& estimated,
                              const Trajectory& groundtruth,
                              const Eigen::Isometry3d& T_world_estworld,
                              const ObjectMetricsOptions& options) {
  Trajectory poses = groundtruth;
  std::stable_sort(poses.begin(), poses.end(), [](const StampedPose& a, const StampedPose& b) {
    return a.stamp_s < b.stamp_s;
  });
  std::vector<double> stamps;
  std::vector<FrameObjects> frames(poses.size());
  for (size_t k = 0; k < poses.size(); ++k) {
    stamps.push_back(poses[k].stamp_s);
    frames[k].camera_position_m = poses[k].T_world_camera.translation();
  }
  ObjectMetrics m;
  m.frames = static_cast<long>(poses.size());
  for (const TruthObject& t : truth) {
    const int k = NearestFrame(stamps, t.stamp_s, options.max_dt_s);
    if (k < 0) {
      ++m.unassociated_truth;
    } else {
      frames[k].truth.push_back(t);
    }
  }
  for (EstimatedObject e : estimated) {
    const int k = NearestFrame(stamps, e.stamp_s, options.max_dt_s);
    if (k < 0) {
      ++m.unassociated_estimates;
      continue;
    }
    e.position_m = T_world_estworld * e.position_m;
    e.velocity_mps = T_world_estworld.linear() * e.velocity_mps;
    frames[k].estimated.push_back(e);
  }
  std::map<int, int> last_match;
  for (const FrameObjects& frame : frames) ScoreFrame(frame, options, &last_match, &m);
  FinishObjectMetrics(&m);
  return m;
}

}  // namespace dslam
