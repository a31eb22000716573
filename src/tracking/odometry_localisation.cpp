// Odometry::StartInMap and the frames before the loaded map localises one: a tracker that starts
// in a saved keyframe map has no pose until a frame is relocalised in it, at a place that place
// recognition (PlaceLookup) names.
#include <limits>
#include <stdexcept>
#include <string>

#include "dslam/tracking/keyframe_window.h"
#include "dslam/tracking/odometry.h"

namespace dslam {
namespace {

// Places (keyframes named by PlaceLookup, best first) tried per frame while localising: each
// costs a descriptor match and a RANSAC.
constexpr size_t kPlacesTriedPerFrame = 3;

}  // namespace

void Odometry::StartInMap(Map map, std::shared_ptr<PlaceLookup> places, double timeout_s,
                          LoadedMapUse use) {
  if (places == nullptr) throw std::invalid_argument("Odometry::StartInMap: no place lookup");
  if (!(timeout_s > 0.0)) throw std::invalid_argument("Odometry::StartInMap: timeout must be > 0");
  if (!config_.tracking.relocalisation) {
    throw std::invalid_argument("Odometry::StartInMap: needs tracking.relocalisation");
  }
  int newest_frame = -1;
  for (const KeyFrame* keyframe : map.AllKeyFrames()) {
    newest_frame = std::max(newest_frame, keyframe->frame_index);
  }
  if (newest_frame == std::numeric_limits<int>::max()) {
    throw std::invalid_argument("Odometry::StartInMap: keyframe frame_index " +
                                std::to_string(newest_frame) +
                                " is the largest int: the next frame's index would overflow");
  }
  Reset(ResetMode::kNewWorld);
  map.ContinueIdsAfter(map_);  // ids unique for the life of the odometry, across starts
  map_ = std::move(map);
  localisation_only_ = use == LoadedMapUse::kLocalisationOnly;
  if (localisation_only_) map_.Freeze();
  frame_index_ = newest_frame + 1;
  places_ = std::move(places);
  localise_timeout_s_ = timeout_s;
  localising_ = true;
}

bool Odometry::LocaliseInLoadedMap(Current* current, int frame_index) {
  if (!RelocaliseAtNamedPlaces(current, frame_index, places_.get())) return false;
  localising_ = false;
  if (!localisation_only_) places_.reset();
  initialised_ = true;
  return true;
}

PlaceLookup* Odometry::LostFramePlaces() const {
  if (map_places_ != nullptr) return map_places_.get();
  return localisation_only_ ? places_.get() : nullptr;
}

bool Odometry::RelocaliseAtNamedPlaces(Current* current, int frame_index, PlaceLookup* places) {
  if (places == nullptr) return false;
  std::vector<int> window_before;
  for (const KeyFrame& keyframe : map_.window()) window_before.push_back(keyframe.id);
  const int recent_before = static_cast<int>(window_before.size() - map_.first_recent_keyframe());
  const std::vector<int> named = places->Candidates(map_, current->features);
  for (size_t i = 0; i < named.size() && i < kPlacesTriedPerFrame; ++i) {
    map_.SetWindowTo(KeyFramesAround(map_, named[i], config_.tracking.window_keyframes));
    current->local_points = map_.LocalPoints({}, StaticSeenSinceFrame());
    if (Relocalise(current, frame_index)) return true;
  }
  if (!named.empty()) map_.SetWindowTo(window_before, recent_before);
  return false;
}

FrameResult Odometry::NotLocalised(Current* current, FrameResult result) {
  result.state = TrackingState::kLocalising;
  result.has_pose = result.has_previous_pose = false;
  result.message = "localising in the loaded keyframe map";
  Summarise(*current, &result);
  return result;
}

}  // namespace dslam
