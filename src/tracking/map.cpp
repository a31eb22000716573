#include "dslam/tracking/map.h"

#include <algorithm>
#include <limits>

#include "dslam/core/geometry.h"
#include "dslam/tracking/id_set.h"
#include "dslam/tracking/keyframe_window.h"

namespace dslam {
namespace {

// An archived keyframe is redundant when this share of its points is observed by at least
// kRedundantObservers other map keyframes (ORB-SLAM2's keyframe culling uses 90 % and 3).
constexpr double kRedundantShare = 0.9;
constexpr int kRedundantObservers = 3;

}  // namespace

PointId Map::AddPoint(MapPoint point) {
  point.id = next_point_id_++;
  const PointId id = point.id;
  points_.emplace(id, std::move(point));
  recently_seen_set_.insert(id);
  recently_seen_.push_back(id);
  return id;
}

MapPoint* Map::Find(PointId id) {
  auto it = points_.find(id);
  return it == points_.end() ? nullptr : &it->second;
}

const MapPoint* Map::Find(PointId id) const {
  auto it = points_.find(id);
  return it == points_.end() ? nullptr : &it->second;
}

void Map::Erase(PointId id) { points_.erase(id); }

const KeyFrame& Map::AddKeyFrame(KeyFrame keyframe, const KeyFrameMapLimits& limits) {
  keyframe.id = next_keyframe_id_++;
  CountObservations(keyframe, +1);
  keyframes_.push_back(std::move(keyframe));
  SetWindow(SelectKeyFrameWindow(*this, limits), limits.recent_keyframes);
  if (frozen_) {  // temporary keyframes live in the window only
    EraseArchived(frozen_keyframes_end_, 0);
    return keyframes_.back();
  }
  const int max_keyframes =
      std::max(limits.max_keyframes, limits.recent_keyframes + limits.covisible_keyframes);
  EraseArchived(std::numeric_limits<int>::min(), static_cast<size_t>(max_keyframes));
  return keyframes_.back();
}

void Map::EraseArchived(int first_id, size_t max_keyframes) {
  auto it = archive_.lower_bound(first_id);
  while (it != archive_.end() && num_keyframes() > max_keyframes) {
    CountObservations(it->second, -1);
    it = archive_.erase(it);
  }
}

void Map::CountObservations(const KeyFrame& keyframe, int delta) {
  for (PointId id : keyframe.points) {
    MapPoint* point = Find(id);
    if (point != nullptr) point->observing_keyframes += delta;
  }
}

void Map::SetWindow(const std::vector<int>& window_ids, int recent_keyframes) {
  EraseRedundant(MoveWindow(window_ids, recent_keyframes));
}

std::vector<int> Map::MoveWindow(const std::vector<int>& window_ids, int recent_keyframes) {
  IdSet in_window(window_ids.size());
  for (int id : window_ids) in_window.Insert(id);
  std::vector<int> archived;
  std::deque<KeyFrame> window;
  for (KeyFrame& keyframe : keyframes_) {
    if (in_window.Contains(keyframe.id)) {
      window.push_back(std::move(keyframe));
    } else {
      archived.push_back(keyframe.id);
      archive_.emplace(keyframe.id, std::move(keyframe));
    }
  }
  for (int id : window_ids) {
    const auto it = archive_.find(id);
    if (it == archive_.end()) continue;
    window.push_back(std::move(it->second));
    archive_.erase(it);
  }
  std::sort(window.begin(), window.end(),
            [](const KeyFrame& a, const KeyFrame& b) { return a.id < b.id; });
  keyframes_ = std::move(window);
  recent_in_window_ = std::min(keyframes_.size(), static_cast<size_t>(recent_keyframes));
  return archived;
}

bool Map::IsRedundant(const KeyFrame& keyframe) const {
  int points = 0, observed = 0;
  for (PointId id : keyframe.points) {
    const MapPoint* point = Find(id);
    if (point == nullptr) continue;
    ++points;
    if (point->observing_keyframes > kRedundantObservers) ++observed;
  }
  return observed >= kRedundantShare * points;
}

void Map::EraseRedundant(const std::vector<int>& ids) {
  for (int id : ids) {
    const auto it = archive_.find(id);
    if (it == archive_.end() || IsFrozenKeyFrame(id) || !IsRedundant(it->second)) continue;
    CountObservations(it->second, -1);
    archive_.erase(it);
  }
}

std::vector<PointId> Map::LocalPoints(const std::vector<PointId>& extra,
                                      int static_seen_since_frame) const {
  size_t bound = extra.size();
  for (const KeyFrame& kf : keyframes_) bound += kf.points.size();
  if (static_seen_since_frame >= 0) bound += recently_seen_.size();
  IdSet seen(bound);
  std::vector<PointId> local;
  local.reserve(bound);
  // An id not in the map is remembered too: its later occurrences are skipped without a lookup.
  auto add = [&](PointId id) {
    if (seen.Insert(id) && points_.count(id)) local.push_back(id);
  };
  for (const KeyFrame& kf : keyframes_) {
    for (PointId id : kf.points) add(id);
  }
  for (PointId id : extra) add(id);
  if (static_seen_since_frame < 0) return local;
  size_t kept = 0;
  for (const PointId id : recently_seen_) {
    const auto it = points_.find(id);
    if (it == points_.end() || it->second.last_seen_frame < static_seen_since_frame) {
      recently_seen_set_.erase(id);  // erased, or not seen since: listed again when seen
      continue;
    }
    recently_seen_[kept++] = id;
    if (it->second.IsVerifiedStatic()) add(id);
  }
  recently_seen_.resize(kept);
  return local;
}

void Map::MarkSeen(MapPoint* point, int frame) {
  point->last_seen_frame = frame;
  if (recently_seen_set_.insert(point->id).second) recently_seen_.push_back(point->id);
}

int Map::Cull(int oldest_frame_to_keep, double min_found_ratio, int min_visible,
              int static_seen_since_frame) {
  int removed = 0;
  for (auto it = points_.begin(); it != points_.end();) {
    const MapPoint& p = it->second;
    if (IsFrozenPoint(p.id)) {
      ++it;
      continue;
    }
    const int keep_since = static_seen_since_frame >= 0 && p.IsVerifiedStatic()
                               ? std::min(oldest_frame_to_keep, static_seen_since_frame)
                               : oldest_frame_to_keep;
    const bool stale = p.last_seen_frame < keep_since && p.observing_keyframes <= 0;
    const bool unreliable =
        p.times_visible >= min_visible && p.times_found < min_found_ratio * p.times_visible;
    if (stale || unreliable) {
      it = points_.erase(it);
      ++removed;
    } else {
      ++it;
    }
  }
  return removed;
}

Map Map::WindowCopy() const {
  Map copy;
  copy.keyframes_ = keyframes_;
  copy.recent_in_window_ = recent_in_window_;
  copy.next_point_id_ = next_point_id_;
  copy.next_keyframe_id_ = next_keyframe_id_;
  copy.frozen_ = frozen_;
  copy.frozen_keyframes_end_ = frozen_keyframes_end_;
  copy.frozen_points_end_ = frozen_points_end_;
  const auto add = [&](PointId id) {
    const auto it = points_.find(id);
    if (it != points_.end()) copy.points_.emplace(id, it->second);
  };
  for (const KeyFrame& keyframe : keyframes_) {
    for (PointId id : keyframe.points) add(id);
    for (const auto& entry : keyframe.measurements.by_point) add(entry.first);
  }
  return copy;
}

KeyFrame* Map::FindKeyFrame(int id) {
  return const_cast<KeyFrame*>(static_cast<const Map&>(*this).FindKeyFrame(id));
}

std::vector<const KeyFrame*> Map::AllKeyFrames() const {
  std::vector<const KeyFrame*> all;
  all.reserve(num_keyframes());
  for (const auto& entry : archive_) all.push_back(&entry.second);
  for (const KeyFrame& keyframe : keyframes_) all.push_back(&keyframe);
  std::sort(all.begin(), all.end(),
            [](const KeyFrame* a, const KeyFrame* b) { return a->id < b->id; });
  return all;
}

const KeyFrame* Map::FindKeyFrame(int id) const {
  for (const KeyFrame& keyframe : keyframes_) {
    if (keyframe.id == id) return &keyframe;
  }
  const auto it = archive_.find(id);
  return it == archive_.end() ? nullptr : &it->second;
}

Eigen::Isometry3d PartialCorrection(const MapCorrection& correction, double s) {
  const Eigen::AngleAxisd rotation(correction.T_new_old.rotation());
  const Eigen::Vector3d& c = correction.pivot_world;
  const Eigen::Vector3d displacement = correction.T_new_old * c - c;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(s * rotation.angle(), rotation.axis()).matrix();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();  // p -> R (p - c) + c + s displacement
  T.linear() = R;
  T.translation() = c - R * c + s * displacement;
  return T;
}

void Map::MoveMadeSince(const MapCorrection& correction) {
  MoveKeyFramesAndPoints(
      [&](const KeyFrame& keyframe) -> std::optional<Eigen::Isometry3d> {
        if (keyframe.frame_index < correction.first_frame) return std::nullopt;
        const auto share = correction.share.find(keyframe.id);
        if (share == correction.share.end()) return correction.T_new_old;
        return PartialCorrection(correction, share->second);
      },
      correction.first_frame, &correction.T_new_old);
}

void Map::CorrectKeyFrames(const std::map<int, Eigen::Isometry3d>& T_world_camera_corrected,
                           const std::map<int, Eigen::Isometry3d>& T_world_camera_before) {
  if (T_world_camera_corrected.empty()) return;
  // T_new_old of a corrected keyframe: from the pose the correction was computed from.
  const auto correction_of = [&](const KeyFrame& keyframe,
                                 const Eigen::Isometry3d& T_world_camera_corrected_k) {
    const auto before = T_world_camera_before.find(keyframe.id);
    const Eigen::Isometry3d& T_world_camera_old =
        before == T_world_camera_before.end() ? keyframe.T_world_camera : before->second;
    return Eigen::Isometry3d(T_world_camera_corrected_k * T_world_camera_old.inverse());
  };
  const int newest_corrected = T_world_camera_corrected.rbegin()->first;
  Eigen::Isometry3d T_new_old_newest = Eigen::Isometry3d::Identity();
  if (const KeyFrame* newest = FindKeyFrame(newest_corrected)) {
    T_new_old_newest = correction_of(*newest, T_world_camera_corrected.rbegin()->second);
  }
  MoveKeyFramesAndPoints(
      [&](const KeyFrame& keyframe) -> std::optional<Eigen::Isometry3d> {
        const auto corrected = T_world_camera_corrected.find(keyframe.id);
        if (corrected != T_world_camera_corrected.end()) {
          return correction_of(keyframe, corrected->second);
        }
        if (keyframe.id < newest_corrected) return std::nullopt;  // not in the correction
        return T_new_old_newest;  // made while the correction was computed
      },
      std::numeric_limits<int>::min(), nullptr);
}

void Map::MoveKeyFramesAndPoints(
    const std::function<std::optional<Eigen::Isometry3d>(const KeyFrame&)>& correction_of,
    int min_created_frame, const Eigen::Isometry3d* before_first) {
  std::map<int, Eigen::Isometry3d> by_frame;  // frame index of a moved keyframe -> its correction
  const auto move = [&](KeyFrame* keyframe) {
    if (IsFrozenKeyFrame(keyframe->id)) return;
    const std::optional<Eigen::Isometry3d> T_new_old = correction_of(*keyframe);
    if (!T_new_old) return;
    keyframe->T_world_camera = *T_new_old * keyframe->T_world_camera;
    keyframe->measurements.T_camera_world = keyframe->T_world_camera.inverse();
    by_frame[keyframe->frame_index] = *T_new_old;
  };
  for (KeyFrame& keyframe : keyframes_) move(&keyframe);
  for (auto& entry : archive_) move(&entry.second);
  for (auto& entry : points_) {
    MapPoint& point = entry.second;
    if (point.created_frame < min_created_frame || IsFrozenPoint(point.id)) continue;
    auto made = by_frame.upper_bound(point.created_frame);
    if (made == by_frame.begin() && before_first == nullptr) continue;
    const Eigen::Isometry3d& T_new_old =
        made == by_frame.begin() ? *before_first : (--made)->second;
    point.p_world = T_new_old * point.p_world;
    point.cov_world = RotatedCovariance(T_new_old.linear(), point.cov_world);
  }
  ++corrections_;
}

void Map::ContinueIdsAfter(const Map& earlier) {
  next_point_id_ = std::max(next_point_id_, earlier.next_point_id_);
  next_keyframe_id_ = std::max(next_keyframe_id_, earlier.next_keyframe_id_);
}

void Map::Clear() {
  points_.clear();
  recently_seen_.clear();
  recently_seen_set_.clear();
  keyframes_.clear();
  archive_.clear();
  recent_in_window_ = 0;
  frozen_ = false;
}

}  // namespace dslam
