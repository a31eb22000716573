#pragma once
// Where in a keyframe map a frame may be, from its features alone (place recognition). The
// tracker asks it when it starts in a loaded keyframe map (Odometry::StartInMap): the window it
// relocalises against is chosen around the keyframes it names. The tracker knows only this
// interface; loop_closing/map_places.h implements it with the bag-of-words place database.

#include <vector>

#include "dslam/features/features.h"
#include "dslam/tracking/map.h"

namespace dslam {

/// Keyframes of a map that may show what a frame shows.
class PlaceLookup {
 public:
  virtual ~PlaceLookup() = default;
  /// Ids of keyframes of `map` that may show the place `features` show, most likely first (at
  /// most a few; empty when none looks alike). Called from the tracking thread only.
  virtual std::vector<int> Candidates(const Map& map, const FrameFeatures& features) = 0;
};

}  // namespace dslam
