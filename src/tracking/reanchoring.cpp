#include "dslam/tracking/reanchoring.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <Eigen/Cholesky>

#include "dslam/core/geometry.h"
#include "dslam/tracking/id_set.h"

namespace dslam {

bool WeakEpisode::Update(int frame_index, int pose_inliers, const TrackingConfig& config) {
  if (!config.reanchoring) return false;
  if (pose_inliers < config.reanchor_weak_inliers) {
    if (first_frame_ < 0) first_frame_ = frame_index;
    return false;
  }
  if (first_frame_ < 0) return false;
  if (frame_index - first_frame_ > kMaxCheckFrames) {
    End();
    return false;
  }
  return pose_inliers >= config.reanchor_strong_inliers &&
         frame_index - first_frame_ >= kMinWeakFrames;
}

std::vector<PointId> VerifiedPointsMadeBefore(const Map& map, int before_frame) {
  IdSet seen(map.size());
  std::vector<PointId> points;
  for (const KeyFrame* keyframe : map.AllKeyFrames()) {
    if (keyframe->frame_index >= before_frame) continue;
    for (PointId id : keyframe->points) {
      const MapPoint* point = map.Find(id);
      if (point == nullptr || !point->IsVerifiedStatic() || point->created_frame >= before_frame)
        continue;
      if (seen.Insert(id)) points.push_back(id);
    }
  }
  return points;
}

double RotationVariance(const Eigen::Matrix<double, 6, 6>& information) {
  const Eigen::LLT<Eigen::Matrix<double, 6, 6>> llt(information);
  if (llt.info() != Eigen::Success) return 0.0;
  const Eigen::Matrix<double, 6, 6> covariance =
      llt.solve(Eigen::Matrix<double, 6, 6>::Identity());
  return covariance.topLeftCorner<3, 3>().trace();
}

namespace {

// The keyframes (window and archive) made from `first_frame` on, oldest first.
std::vector<const KeyFrame*> KeyFramesMadeSince(const Map& map, int first_frame) {
  std::vector<const KeyFrame*> made = map.AllKeyFrames();
  made.erase(std::remove_if(made.begin(), made.end(),
                            [&](const KeyFrame* k) { return k->frame_index < first_frame; }),
             made.end());
  return made;
}

}  // namespace

std::map<int, double> CorrectionShares(const Map& map, int first_frame,
                                       const Eigen::Matrix<double, 6, 6>& current_information) {
  const std::vector<const KeyFrame*> made = KeyFramesMadeSince(map, first_frame);
  std::vector<double> cumulative;
  double sum = 0.0;
  for (const KeyFrame* keyframe : made) {
    sum += RotationVariance(keyframe->information);
    cumulative.push_back(sum);
  }
  const double total = sum + RotationVariance(current_information);
  std::map<int, double> share;
  for (size_t k = 0; k < made.size(); ++k) {
    share[made[k]->id] = total > 0.0 ? cumulative[k] / total
                                     : static_cast<double>(k + 1) / (made.size() + 1);
  }
  return share;
}

Eigen::Vector3d CorrectionPivot(const Map& map, int first_frame) {
  const std::vector<const KeyFrame*> all = map.AllKeyFrames();  // oldest first
  const auto since = std::find_if(all.begin(), all.end(), [&](const KeyFrame* k) {
    return k->frame_index >= first_frame;
  });
  if (since != all.begin()) return (*std::prev(since))->T_world_camera.translation();
  if (since != all.end()) return (*since)->T_world_camera.translation();
  return Eigen::Vector3d::Zero();
}

bool CorrectionWorthApplying(const Eigen::Isometry3d& T_new_old, const TrackingConfig& config) {
  return T_new_old.translation().norm() >= config.reanchor_min_correction_m ||
         RotationAngleDeg(T_new_old.rotation()) >= config.reanchor_min_correction_deg;
}

}  // namespace dslam
