#pragma once
// Which keyframes of the keyframe map form the window: the keyframes whose points tracking
// searches (Map::LocalPoints) and the back end refines (LocalMappingJob). The newest keyframes
// always belong to it; older keyframes join it when they share points with the newest keyframe
// (covisibility) or when the newest keyframe's camera is near theirs (a view the camera returns
// to, whose points tracking has not matched yet, so that covisibility cannot find them).

#include <utility>
#include <vector>

#include "dslam/tracking/map.h"

namespace dslam {

/// [points] Older keyframes sharing fewer points with the newest keyframe are not covisible.
constexpr int kMinCovisiblePoints = 15;
/// [m] and [deg] An older keyframe is near the newest one when their camera centres are at most
/// this far apart and their optical axes at most this angle.
constexpr double kNearbyKeyFrameM = 0.3;
constexpr double kNearbyKeyFrameDeg = 20.0;

/// Ids of the window for the map's newest keyframe (the last of map.window()), ascending:
/// the newest `limits.recent_keyframes` keyframes of the map, then up to
/// `limits.covisible_keyframes` older ones, half of the places first to the nearby keyframes
/// that share no points with it (nearest first), the rest by the number of points shared with
/// the newest keyframe (most first); places left go to the other list. In a frozen map
/// (Map::Freeze, localisation only) the older keyframes are the frozen ones only, and at least
/// `limits.recent_keyframes` of them are added.
std::vector<int> SelectKeyFrameWindow(const Map& map, const KeyFrameMapLimits& limits);

/// (keyframe id, number of the points `keyframe` lists that it lists too) for every other
/// keyframe of `map` (window and archive) sharing at least `min_shared` (>= 1) of them, ascending
/// id. One pass over the map's keyframe point lists: for one keyframe's covisibility; every
/// keyframe's at once is loop_closing's CovisibilityIndex.
std::vector<std::pair<int, int>> SharedPointCounts(const Map& map, const KeyFrame& keyframe,
                                                   int min_shared);

/// Ids of the keyframe `keyframe_id` and of up to `size` - 1 keyframes of the map sharing the
/// most points (at least kMinCovisiblePoints) with it, ascending; empty when it is not in the map.
/// The window of a tracker relocalising at a place that place recognition named.
std::vector<int> KeyFramesAround(const Map& map, int keyframe_id, int size);

}  // namespace dslam
