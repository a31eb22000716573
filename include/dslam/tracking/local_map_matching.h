#pragma once
// Matching the local map to a frame's features by projection (paper Sec. V-B: marked and
// unmarked points are both matched, so features on moving objects are claimed by unmarked
// points instead of becoming new marked points).

#include <vector>

#include <Eigen/Geometry>

#include "dslam/features/features.h"
#include "dslam/tracking/map.h"

namespace dslam {

/// A map point matched to a feature of the current frame.
struct PointMatch {
  PointId id = -1;   ///< map point
  int feature = -1;  ///< index into FrameFeatures::features
};

/// Projects the map points `candidates` into the frame with `T_camera_world`, and searches each
/// projected point's best feature within `radius_px` (scaled by the feature octave) among the
/// features not yet in `feature_taken`. Matched features are marked taken. Points closer than
/// `min_depth_m` [m] along the optical axis (so also points behind the camera) or outside the
/// image are skipped; when `count_visible`, every point that projects into the image has
/// times_visible incremented (the found ratio used by map culling).
std::vector<PointMatch> MatchLocalMap(Map* map, const std::vector<PointId>& candidates,
                                      const FrameFeatures& features, const PinholeCamera& camera,
                                      const Eigen::Isometry3d& T_camera_world, double radius_px,
                                      double min_depth_m, bool count_visible,
                                      std::vector<bool>* feature_taken);

}  // namespace dslam
