#pragma once
// Place recognition over the whole keyframe map for the tracker (PlaceLookup): where a tracker
// that starts in a loaded keyframe map may be (Odometry::StartInMap). Each keyframe's words are
// those loop detection gives it (Vocabulary::Transform of the descriptors of its verified static
// points measured in it, StaticMeasuredPoints), so that points on people never name a place; a
// frame's words are those of all its ORB descriptors, since its points are not labelled yet.

#include <memory>
#include <set>
#include <vector>

#include "dslam/place_recognition/place_database.h"
#include "dslam/place_recognition/vocabulary.h"
#include "dslam/tracking/place_lookup.h"

namespace dslam {

/// Places a frame may show: the kMaxPlaces keyframes of the map whose words score highest
/// against the frame's (PlaceDatabase::Query).
class MapPlaces : public PlaceLookup {
 public:
  /// Keyframes named per query, at most.
  static constexpr int kMaxPlaces = 3;

  /// Throws std::invalid_argument when `vocabulary` is null or empty.
  explicit MapPlaces(std::shared_ptr<const Vocabulary> vocabulary);

  /// The best-scoring keyframes of `map` for `features`, best first. The database is filled at
  /// the first call with every keyframe of `map`, takes keyframes added since at later calls and
  /// drops those the map erased (it stays as bounded as the map). Of a frozen map (Map::Freeze)
  /// only the frozen keyframes enter.
  std::vector<int> Candidates(const Map& map, const FrameFeatures& features) override;

  /// Keyframes in the database.
  std::size_t size() const { return database_.size(); }

 private:
  std::shared_ptr<const Vocabulary> vocabulary_;
  PlaceDatabase database_;
  std::set<int> ids_;  ///< keyframes in database_
};

}  // namespace dslam
