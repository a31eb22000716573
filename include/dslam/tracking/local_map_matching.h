#pragma once
// Matching the local map to a frame's features by projection (paper Sec. V-B: marked and
// unmarked points are both matched, so features on moving objects are claimed by unmarked
// points instead of becoming new marked points).

#include <vector>

#include <Eigen/Geometry>

#include "dslam/features/features.h"
#include "dslam/features/matching.h"
#include "dslam/tracking/map.h"

namespace dslam {

/// A map point matched to a feature of the current frame.
struct PointMatch {
  PointId id = -1;   ///< map point
  int feature = -1;  ///< index into FrameFeatures::features
};

/// How MatchLocalMap searches.
struct LocalMapSearch {
  double radius_px = 10.0;  ///< [px] search radius at octave 0
  /// [m] points nearer than this along the optical axis (so also points behind the camera) are
  /// skipped.
  double min_depth_m = 0.1;
  /// MatchLocalMap increments times_visible of every point that projects into the image (the found
  /// ratio used by map culling); otherwise it writes no map point.
  bool count_visible = false;
  /// When set, a marked point measured (with depth) in this frame is projected from that
  /// measurement, moved into the world with the frame's pose, instead of from its p_world (where
  /// it was created, unless fused or refined): it is searched where it was seen one frame ago.
  const FrameMeasurements* last_frame = nullptr;
};

/// Map points projected into a frame, ready for ClaimLocalMapMatches.
struct ProjectedLocalMap {
  std::vector<ProjectedPoint> points;  ///< projections with their radii and descriptors
  std::vector<PointId> ids;            ///< the map point of each element of `points`
};

/// Projects the map points `candidates` into the frame with `T_camera_world`, each with its
/// search radius from `search` and from p_world (or from its
/// measurement in search.last_frame). Points nearer than search.min_depth_m
/// or outside the image are skipped; search.count_visible is not read here (see MatchLocalMap).
ProjectedLocalMap ProjectLocalMap(const Map& map, const std::vector<PointId>& candidates,
                                  const FrameFeatures& features, const PinholeCamera& camera,
                                  const Eigen::Isometry3d& T_camera_world,
                                  const LocalMapSearch& search);

/// Searches each projected point's best feature within its radius (scaled by the feature octave)
/// among the features not yet in `feature_taken`; matched features are marked taken. Reads no map
/// point.
std::vector<PointMatch> ClaimLocalMapMatches(const ProjectedLocalMap& projected,
                                             const FrameFeatures& features,
                                             std::vector<bool>* feature_taken);

/// ProjectLocalMap, then (when search.count_visible) times_visible incremented for every projected
/// point that is not frozen (Map::Freeze), then ClaimLocalMapMatches.
std::vector<PointMatch> MatchLocalMap(Map* map, const std::vector<PointId>& candidates,
                                      const FrameFeatures& features, const PinholeCamera& camera,
                                      const Eigen::Isometry3d& T_camera_world,
                                      const LocalMapSearch& search,
                                      std::vector<bool>* feature_taken);

}  // namespace dslam
