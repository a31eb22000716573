#include "dslam/loop_closing/map_places.h"

#include <set>
#include <stdexcept>

#include "dslam/loop_closing/loop_verification.h"

namespace dslam {

MapPlaces::MapPlaces(std::shared_ptr<const Vocabulary> vocabulary)
    : vocabulary_(std::move(vocabulary)) {
  if (vocabulary_ == nullptr || vocabulary_->empty()) {
    throw std::invalid_argument("MapPlaces: no vocabulary");
  }
}

std::vector<int> MapPlaces::Candidates(const Map& map, const FrameFeatures& features) {
  std::set<int> in_map;
  for (const KeyFrame* keyframe : map.AllKeyFrames()) {
    // Localisation only: the places are the loaded (frozen) map's, not the temporary keyframes.
    if (map.frozen() && !map.IsFrozenKeyFrame(keyframe->id)) continue;
    in_map.insert(keyframe->id);
    if (database_.Contains(keyframe->id)) continue;
    const cv::Mat descriptors = PointDescriptors(map, StaticMeasuredPoints(map, *keyframe));
    if (!descriptors.empty()) database_.Add(keyframe->id, vocabulary_->Transform(descriptors));
    ids_.insert(keyframe->id);
  }
  for (auto it = ids_.begin(); it != ids_.end();) {  // keyframes the map erased
    if (in_map.count(*it) != 0) {
      ++it;
      continue;
    }
    database_.Erase(*it);
    it = ids_.erase(it);
  }
  if (features.descriptors.empty()) return {};
  PlaceQueryOptions options;
  options.max_results = kMaxPlaces;
  std::vector<int> ids;
  for (const PlaceCandidate& candidate :
       database_.Query(vocabulary_->Transform(features.descriptors), options)) {
    ids.push_back(candidate.id);
  }
  return ids;
}

}  // namespace dslam
