#include "dslam/tracking/map.h"

#include <algorithm>

#include "dslam/tracking/id_set.h"

namespace dslam {

PointId Map::AddPoint(MapPoint point) {
  point.id = next_point_id_++;
  const PointId id = point.id;
  points_.emplace(id, std::move(point));
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

const KeyFrame& Map::AddKeyFrame(KeyFrame keyframe, int max_keyframes) {
  keyframe.id = next_keyframe_id_++;
  keyframes_.push_back(std::move(keyframe));
  while (static_cast<int>(keyframes_.size()) > max_keyframes) keyframes_.pop_front();
  return keyframes_.back();
}

std::vector<PointId> Map::LocalPoints(const std::vector<PointId>& extra,
                                      int static_seen_since_frame) const {
  size_t bound = extra.size();
  for (const KeyFrame& kf : keyframes_) bound += kf.points.size();
  if (static_seen_since_frame >= 0) bound += points_.size();
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
  for (const auto& [id, point] : points_) {
    if (point.IsVerifiedStatic() && point.last_seen_frame >= static_seen_since_frame) add(id);
  }
  return local;
}

int Map::Cull(int oldest_frame_to_keep, double min_found_ratio, int min_visible,
              int static_seen_since_frame) {
  size_t window_points = 0;
  for (const KeyFrame& kf : keyframes_) window_points += kf.points.size();
  IdSet in_window(window_points);
  for (const KeyFrame& kf : keyframes_) {
    for (PointId id : kf.points) in_window.Insert(id);
  }
  int removed = 0;
  for (auto it = points_.begin(); it != points_.end();) {
    const MapPoint& p = it->second;
    const int keep_since = static_seen_since_frame >= 0 && p.IsVerifiedStatic()
                               ? std::min(oldest_frame_to_keep, static_seen_since_frame)
                               : oldest_frame_to_keep;
    const bool stale = p.last_seen_frame < keep_since && !in_window.Contains(p.id);
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
  copy.next_point_id_ = next_point_id_;
  copy.next_keyframe_id_ = next_keyframe_id_;
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
  for (KeyFrame& keyframe : keyframes_) {
    if (keyframe.id == id) return &keyframe;
  }
  return nullptr;
}

void Map::Clear() {
  points_.clear();
  keyframes_.clear();
}

}  // namespace dslam
