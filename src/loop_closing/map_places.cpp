#include "dslam/loop_closing/map_places.h"

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
  for (const KeyFrame* keyframe : map.AllKeyFrames()) {
    if (database_.Contains(keyframe->id)) continue;
    const cv::Mat descriptors = PointDescriptors(map, StaticMeasuredPoints(map, *keyframe));
    if (!descriptors.empty()) database_.Add(keyframe->id, vocabulary_->Transform(descriptors));
  }
  if (features.descriptors.empty()) return {};
  PlaceQueryOptions options;
  options.max_results = kMaxPlaces;
  options.exclude = [&](int id) { return map.FindKeyFrame(id) == nullptr; };
  std::vector<int> ids;
  for (const PlaceCandidate& candidate :
       database_.Query(vocabulary_->Transform(features.descriptors), options)) {
    ids.push_back(candidate.id);
  }
  return ids;
}

}  // namespace dslam
