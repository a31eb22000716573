#include "dslam/tracking/reanchoring.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

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
  const auto collect = [&](const KeyFrame& keyframe) {
    if (keyframe.frame_index >= before_frame) return;
    for (PointId id : keyframe.points) {
      const MapPoint* point = map.Find(id);
      if (point == nullptr || !point->IsVerifiedStatic() || point->created_frame >= before_frame)
        continue;
      if (seen.Insert(id)) points.push_back(id);
    }
  };
  for (const auto& entry : map.archived_keyframes()) collect(entry.second);
  for (const KeyFrame& keyframe : map.keyframes()) collect(keyframe);
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
  std::vector<const KeyFrame*> out;
  for (const auto& entry : map.archived_keyframes()) {
    if (entry.second.frame_index >= first_frame) out.push_back(&entry.second);
  }
  for (const KeyFrame& keyframe : map.keyframes()) {
    if (keyframe.frame_index >= first_frame) out.push_back(&keyframe);
  }
  std::sort(out.begin(), out.end(), [](const KeyFrame* a, const KeyFrame* b) {
    return a->frame_index < b->frame_index;
  });
  return out;
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
  const KeyFrame* before = nullptr;
  const KeyFrame* oldest_since = nullptr;
  const auto consider = [&](const KeyFrame& keyframe) {
    if (keyframe.frame_index < first_frame) {
      if (before == nullptr || keyframe.frame_index > before->frame_index) before = &keyframe;
    } else if (oldest_since == nullptr || keyframe.frame_index < oldest_since->frame_index) {
      oldest_since = &keyframe;
    }
  };
  for (const auto& entry : map.archived_keyframes()) consider(entry.second);
  for (const KeyFrame& keyframe : map.keyframes()) consider(keyframe);
  const KeyFrame* pivot = before != nullptr ? before : oldest_since;
  return pivot != nullptr ? Eigen::Vector3d(pivot->T_world_camera.translation())
                          : Eigen::Vector3d::Zero();
}

bool CorrectionWorthApplying(const Eigen::Isometry3d& T_new_old, const TrackingConfig& config) {
  const double angle_deg = Eigen::AngleAxisd(T_new_old.rotation()).angle() * 180.0 / M_PI;
  return T_new_old.translation().norm() >= config.reanchor_min_correction_m ||
         angle_deg >= config.reanchor_min_correction_deg;
}

}  // namespace dslam
