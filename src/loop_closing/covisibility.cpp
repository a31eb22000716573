#include "dslam/loop_closing/covisibility.h"

#include <algorithm>
#include <map>

namespace dslam {

CovisibilityIndex::CovisibilityIndex(const Map& map) {
  const auto add = [this](const KeyFrame& keyframe) {
    for (PointId id : keyframe.points) observers_[id].push_back(keyframe.id);
  };
  for (const KeyFrame& keyframe : map.window()) add(keyframe);
  for (const auto& [id, keyframe] : map.archived_keyframes()) add(keyframe);
}

std::vector<std::pair<int, int>> CovisibilityIndex::Covisible(const KeyFrame& keyframe) const {
  std::map<int, int> shared;  // keyframe id -> shared points
  for (PointId id : keyframe.points) {
    const auto it = observers_.find(id);
    if (it == observers_.end()) continue;
    for (int other : it->second) {
      if (other != keyframe.id) ++shared[other];
    }
  }
  std::vector<std::pair<int, int>> out(shared.begin(), shared.end());
  std::stable_sort(out.begin(), out.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  return out;
}

}  // namespace dslam
