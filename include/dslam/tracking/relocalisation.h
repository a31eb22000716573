#pragma once
// Relocalisation by descriptors. The projection search (local_map_matching.h) needs a pose
// prediction; after a jump (frames missing from the input, a fast turn, a covered lens) the
// prediction is useless and the frame is lost. Descriptor matching needs no prediction: every
// feature with a depth measurement is matched by brute force (Hamming distance, ratio test)
// against the descriptors of the marked map points the window's keyframes observe, and a RANSAC
// over the 3D-3D correspondences of marked points only decides the pose (a crowd filling the view
// cannot win it: its points are unmarked). The window holds at most tracking.window_keyframes
// keyframes, so the search costs one brute-force match of ~1000 features against a few thousand
// descriptors, paid only in frames whose prediction failed.

#include <vector>

#include "dslam/features/features.h"
#include "dslam/tracking/local_map_matching.h"
#include "dslam/tracking/map.h"

namespace dslam {

/// Acceptance rules of a descriptor match (MatchBruteForce); relocalisation uses the defaults.
struct DescriptorMatchRules {
  int max_distance_bits = 64;  ///< [bits] of 256: a match must be nearer than this
  double ratio = 0.8;          ///< [-] and nearer than ratio x the second nearest
};

/// The marked map points observed by the window's keyframes (KeyFrame::points), each once, in
/// the order of first observation (oldest keyframe first).
std::vector<PointId> WindowMarkedPoints(const Map& map);

/// Matches of the features with a depth measurement to `points` by descriptor alone (no pose):
/// at most one point per feature and one feature per point, sorted by feature index.
std::vector<PointMatch> MatchByDescriptor(const Map& map, const std::vector<PointId>& points,
                                          const FrameFeatures& features,
                                          const DescriptorMatchRules& rules);

}  // namespace dslam
