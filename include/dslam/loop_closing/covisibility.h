#pragma once
// Which keyframes of a keyframe map see the same map points (covisibility) for every keyframe at
// once, for the loop pose graph's covisibility edges (loop_correction.h): an index from each map
// point to the keyframes listing it (KeyFrame::points), built from the window and the archive of
// one Map at one moment. One keyframe's covisibility (loop detection, relocalisation) is
// SharedPointCounts (tracking/keyframe_window.h): a pass over the point lists that allocates
// nothing per point, where this index allocates a list per point.

#include <cstddef>
#include <unordered_map>
#include <utility>
#include <vector>

#include "dslam/tracking/map.h"

namespace dslam {

/// Map point -> keyframes that list it, over every keyframe of a map (window and archive).
class CovisibilityIndex {
 public:
  /// Indexes the points that `map`'s keyframes list now; later changes of the map are not seen.
  explicit CovisibilityIndex(const Map& map);

  /// (keyframe id, number of points shared with `keyframe`) for every other keyframe of the map
  /// sharing at least one point with it, most shared points first (ties: lower id first).
  std::vector<std::pair<int, int>> Covisible(const KeyFrame& keyframe) const;

  std::size_t num_points() const { return observers_.size(); }  ///< points with observers

 private:
  std::unordered_map<PointId, std::vector<int>> observers_;  // point -> keyframe ids
};

}  // namespace dslam
