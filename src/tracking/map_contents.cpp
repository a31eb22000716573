// Map::Contents, Map::FromContents, Map::SetWindowTo and Map::Freeze: a keyframe map as plain
// lists and back (a saved keyframe map), the window a tracker starting in a loaded map begins
// with, and a loaded map frozen for localisation only.
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_set>

#include "dslam/tracking/map.h"

namespace dslam {

MapContents Map::Contents() const {
  MapContents contents;
  contents.points.reserve(points_.size());
  for (const auto& entry : points_) contents.points.push_back(entry.second);
  std::sort(contents.points.begin(), contents.points.end(),
            [](const MapPoint& a, const MapPoint& b) { return a.id < b.id; });
  for (const KeyFrame* keyframe : AllKeyFrames()) contents.keyframes.push_back(*keyframe);
  return contents;
}

Map Map::FromContents(MapContents contents) {
  Map map;
  for (MapPoint& point : contents.points) {
    if (point.id < 0)
      throw std::invalid_argument("map point with negative id " + std::to_string(point.id));
    if (point.id == std::numeric_limits<PointId>::max()) {
      throw std::invalid_argument("map point id " + std::to_string(point.id) +
                                  " is the largest PointId: the next point's id would overflow");
    }
    point.observing_keyframes = 0;
    map.next_point_id_ = std::max(map.next_point_id_, point.id + 1);
    const PointId id = point.id;
    if (!map.points_.emplace(id, std::move(point)).second) {
      throw std::invalid_argument("map point id " + std::to_string(id) + " repeats");
    }
    map.recently_seen_set_.insert(id);  // LocalPoints drops those not seen recently
    map.recently_seen_.push_back(id);
  }
  for (KeyFrame& keyframe : contents.keyframes) {
    if (keyframe.id < 0)
      throw std::invalid_argument("keyframe with negative id " + std::to_string(keyframe.id));
    if (keyframe.id == std::numeric_limits<int>::max()) {
      throw std::invalid_argument("keyframe id " + std::to_string(keyframe.id) +
                                  " is the largest int: the next keyframe's id would overflow");
    }
    auto& ids = keyframe.points;
    ids.erase(
        std::remove_if(ids.begin(), ids.end(), [&](PointId id) { return map.Find(id) == nullptr; }),
        ids.end());
    map.next_keyframe_id_ = std::max(map.next_keyframe_id_, keyframe.id + 1);
    map.CountObservations(keyframe, +1);
    const int id = keyframe.id;
    if (!map.archive_.emplace(id, std::move(keyframe)).second) {
      throw std::invalid_argument("keyframe id " + std::to_string(id) + " repeats");
    }
  }
  return map;
}

void Map::SetWindowTo(const std::vector<int>& ids, int recent) {
  std::vector<int> present;
  for (int id : ids) {
    if (FindKeyFrame(id) != nullptr) present.push_back(id);
  }
  std::sort(present.begin(), present.end());
  present.erase(std::unique(present.begin(), present.end()), present.end());
  const int size = static_cast<int>(present.size());
  MoveWindow(present, recent < 0 ? size : std::min(recent, size));
}

void Map::Freeze() {
  frozen_ = true;
  frozen_keyframes_end_ = next_keyframe_id_;
  frozen_points_end_ = next_point_id_;
}

MapPoint* Map::FindWritable(PointId id) { return IsFrozenPoint(id) ? nullptr : Find(id); }

}  // namespace dslam
