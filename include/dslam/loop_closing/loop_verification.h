#pragma once
// Geometric verification of a loop candidate on verified static points only: the query
// keyframe's verified static points measured in it (y_camera, C) are matched by descriptor
// (never by point id: a loop means the map made the place twice, so the two sides hold different
// map points) to the verified static points of the match keyframe and its covisible neighbours
// at their map positions p_world; a 3D-3D RANSAC and motion-only BA (EstimatePoseRobust,
// robust_pose.h) then place the query camera in the match side's world. Points on people
// (unmarked) and new points (candidates) take no part.

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/core/camera.h"
#include "dslam/core/features_config.h"
#include "dslam/core/loop_closing_config.h"
#include "dslam/tracking/map.h"

namespace dslam {

/// The points of `keyframe` that take part in loop detection: those it lists (KeyFrame::points)
/// that are in the map, IsVerifiedStatic(), carry a descriptor and have a measurement in it
/// (measurements.by_point); in the order of KeyFrame::points, each once.
std::vector<PointId> StaticMeasuredPoints(const Map& map, const KeyFrame& keyframe);

/// Their descriptors, one 1x32 CV_8U row per point in the order of `points` (empty without any).
cv::Mat PointDescriptors(const Map& map, const std::vector<PointId>& points);

/// How many of the 4 image quadrants (split at width/2 and height/2 [px]) hold the projection of
/// at least one of `y_camera` ([m], optical frame; points with z <= 0 are skipped).
int ImageQuadrants(const std::vector<Eigen::Vector3d>& y_camera, const PinholeCamera& camera);

/// Outcome of VerifyLoop.
struct LoopVerification {
  bool accepted = false;  ///< the pose was found and passed every rule of LoopClosingConfig
  /// [m] query camera (optical frame) in the match side's world; identity when RANSAC failed.
  Eigen::Isometry3d T_world_query = Eigen::Isometry3d::Identity();
  int matches = 0;    ///< descriptor matches
  int inliers = 0;    ///< of them, inliers of the refined pose (chi-square on y_camera)
  int quadrants = 0;  ///< image quadrants of the query keyframe the inliers reach (0..4)
};

/// Verifies `query` against the verified static points (StaticMeasuredPoints' rule without the
/// measurement: IsVerifiedStatic, with a descriptor) listed by the keyframes `match_side` (ids;
/// ones not in the map are skipped), leaving out points `query` lists itself. Accepted when the
/// refined pose has inliers >= config.min_inliers and >= config.min_inlier_share x matches and
/// they reach config.min_image_quadrants quadrants. `seed` seeds the RANSAC.
LoopVerification VerifyLoop(const Map& map, const KeyFrame& query,
                            const std::vector<int>& match_side, const PinholeCamera& camera,
                            const LoopClosingConfig& config, const PoseConfig& pose_config,
                            std::uint32_t seed);

}  // namespace dslam
