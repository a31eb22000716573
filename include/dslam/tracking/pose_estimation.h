#pragma once
// Camera pose from map-point matches: motion-only bundle adjustment over marked (static) points,
// and a robust RANSAC pose over all matches for recovery (pose_optimizer.h, robust_pose.h).

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "dslam/core/config.h"
#include "dslam/features/features.h"
#include "dslam/tracking/local_map_matching.h"
#include "dslam/tracking/map.h"
#include "dslam/tracking/pose_optimizer.h"

namespace dslam {

/// Which matched map points a pose estimate uses.
enum class PointSelection {
  kVerified,  ///< marked and verified (no candidates)
  kMarked,    ///< marked, candidates included
  kAll,       ///< every match
};

/// Motion-only BA (Huber, chi-square inlier rounds) from `T_camera_world_init` over the matches
/// whose map point is `selection`. Matches with a depth
/// measurement give 3D residuals whitened by C_ik plus the map point's covariance, the others 2D
/// reprojection residuals (1 px x octave scale). Matches flagged in `excluded` (parallel to
/// `matches`, may be empty) are left out. The result's `inliers` is parallel to `matches`
/// (matches left out: false).
PoseResult EstimatePoseFromMatches(const Map& map, const std::vector<PointMatch>& matches,
                                   const FrameFeatures& features, const PinholeCamera& camera,
                                   const Eigen::Isometry3d& T_camera_world_init,
                                   PointSelection selection, const std::vector<bool>& excluded,
                                   const Config& config);

/// RANSAC over the 3D-3D correspondences of the matches whose map point is `selection`, refined
/// by motion-only BA; `inliers` parallel to `matches` (matches left out: false). Deterministic for
/// a given `seed`.
PoseResult EstimateRobustPoseFromMatches(const Map& map, const std::vector<PointMatch>& matches,
                                         const FrameFeatures& features, const PinholeCamera& camera,
                                         PointSelection selection, const Config& config,
                                         uint32_t seed);

}  // namespace dslam
