#include "dslam/tracking/keyframe_window.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "dslam/tracking/id_set.h"

namespace dslam {
namespace {

/// Every keyframe of the map, newest first.
std::vector<const KeyFrame*> NewestFirst(const Map& map) {
  std::vector<const KeyFrame*> all = map.AllKeyFrames();
  std::reverse(all.begin(), all.end());
  return all;
}

int SharedPoints(const KeyFrame& keyframe, const IdSet& points) {
  int shared = 0;
  for (PointId id : keyframe.points) shared += points.Contains(id) ? 1 : 0;
  return shared;
}

/// [m] Camera-centre distance when the optical axes are within kNearbyKeyFrameDeg, else < 0.
double NearbyDistance(const KeyFrame& a, const KeyFrame& b) {
  const double cos_angle = a.T_world_camera.linear().col(2).dot(b.T_world_camera.linear().col(2));
  if (cos_angle < std::cos(kNearbyKeyFrameDeg * M_PI / 180.0)) return -1.0;
  const double distance = (a.T_world_camera.translation() - b.T_world_camera.translation()).norm();
  return distance <= kNearbyKeyFrameM ? distance : -1.0;
}

/// (score, id) pairs sorted best first: higher score first, then newer.
using Ranked = std::vector<std::pair<double, int>>;
void SortBestFirst(Ranked* ranked) {
  std::sort(ranked->begin(), ranked->end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second > b.second;
  });
}

}  // namespace

std::vector<int> SelectKeyFrameWindow(const Map& map, const KeyFrameMapLimits& limits) {
  const std::vector<const KeyFrame*> all = NewestFirst(map);
  const size_t recent = std::min(all.size(), static_cast<size_t>(limits.recent_keyframes));
  std::vector<int> window;
  for (size_t i = 0; i < recent; ++i) window.push_back(all[i]->id);
  // A frozen map (localisation only): the newest keyframes are temporary ones, so as many loaded
  // keyframes around the pose join them at least, or tracking would search the temporary
  // keyframes' new points alone.
  const int places_wanted = map.frozen()
                                ? std::max(limits.covisible_keyframes, limits.recent_keyframes)
                                : limits.covisible_keyframes;
  if (all.empty() || places_wanted <= 0) {
    std::sort(window.begin(), window.end());
    return window;
  }
  const KeyFrame& newest = *all.front();
  IdSet newest_points(newest.points.size());
  for (PointId id : newest.points) newest_points.Insert(id);
  Ranked covisible, nearby;
  for (size_t i = recent; i < all.size(); ++i) {
    // A frozen map's older temporary keyframes leave it (Map::AddKeyFrame): only loaded ones join.
    if (map.frozen() && !map.IsFrozenKeyFrame(all[i]->id)) continue;
    const int shared = SharedPoints(*all[i], newest_points);
    if (shared >= kMinCovisiblePoints) {
      covisible.emplace_back(shared, all[i]->id);
      continue;
    }
    const double distance = NearbyDistance(newest, *all[i]);
    if (distance >= 0.0) nearby.emplace_back(-distance, all[i]->id);
  }
  SortBestFirst(&covisible);
  SortBestFirst(&nearby);
  const size_t places = static_cast<size_t>(places_wanted);
  const size_t from_nearby =
      std::min(nearby.size(), std::max(places / 2, places - std::min(places, covisible.size())));
  const size_t from_covisible = std::min(covisible.size(), places - from_nearby);
  for (size_t i = 0; i < from_nearby; ++i) window.push_back(nearby[i].second);
  for (size_t i = 0; i < from_covisible; ++i) window.push_back(covisible[i].second);
  std::sort(window.begin(), window.end());
  return window;
}

std::vector<std::pair<int, int>> SharedPointCounts(const Map& map, const KeyFrame& keyframe,
                                                   int min_shared) {
  IdSet points(keyframe.points.size());
  for (PointId id : keyframe.points) points.Insert(id);
  std::vector<std::pair<int, int>> counts;
  for (const KeyFrame* other : map.AllKeyFrames()) {  // ascending id
    if (other->id == keyframe.id) continue;
    const int shared = SharedPoints(*other, points);
    if (shared >= std::max(min_shared, 1)) counts.emplace_back(other->id, shared);
  }
  return counts;
}

std::vector<int> KeyFramesAround(const Map& map, int keyframe_id, int size) {
  const KeyFrame* centre = map.FindKeyFrame(keyframe_id);
  if (centre == nullptr || size <= 0) return {};
  Ranked covisible;
  for (const auto& [id, shared] : SharedPointCounts(map, *centre, kMinCovisiblePoints)) {
    covisible.emplace_back(shared, id);
  }
  SortBestFirst(&covisible);
  std::vector<int> around{keyframe_id};
  for (size_t i = 0; i < covisible.size() && around.size() < static_cast<size_t>(size); ++i) {
    around.push_back(covisible[i].second);
  }
  std::sort(around.begin(), around.end());
  return around;
}

}  // namespace dslam
