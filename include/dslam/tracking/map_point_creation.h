#pragma once
// Creating map points at keyframes from features with depth (paper Sec. V-C, second creation
// method). New points start marked (paper), except where the image neighbourhood is dominated by
// points already known to move: a new feature on a walking person would otherwise be trusted
// until the next static point determination catches it.

#include <vector>

#include <Eigen/Geometry>

#include "dslam/core/tracking_config.h"
#include "dslam/features/features.h"
#include "dslam/tracking/local_map_matching.h"
#include "dslam/tracking/map.h"

namespace dslam {

/// Frame facts that new points record.
struct CreationContext {
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();  ///< keyframe pose
  int frame_index = 0;                     ///< frame the keyframe was made from
  bool new_points_are_candidates = false;  ///< new points wait for verification (see MapPoint)
};

/// Per feature, whether its tracked image neighbours (matched map points within `radius_px`)
/// are mostly unmarked: -1 when they are not (unmarked ones do not outnumber marked ones),
/// otherwise the median MapPoint::dynamic_frames of the unmarked neighbours (>= 0), which a new
/// point there inherits (it was seen moving as long as its object).
std::vector<int> DynamicNeighbourhood(const FrameFeatures& features,
                                      const std::vector<PointMatch>& matches, const Map& map,
                                      double radius_px);

/// Adds map points for up to config.max_new_points features that have a depth measurement and
/// no match (`feature_taken` false), nearest first (ORB-SLAM2's RGB-D rule: close points are the
/// best constrained). Position p_world = T_world_camera y, covariance R C R^T. A point whose
/// `dynamic_neighbourhood` entry is >= 0 starts unmarked with that many dynamic frames
/// (DynamicNeighbourhood); -1: marked (a candidate when context says so). Returns their ids.
std::vector<PointId> CreateMapPoints(const FrameFeatures& features,
                                     const std::vector<bool>& feature_taken,
                                     const std::vector<int>& dynamic_neighbourhood,
                                     const CreationContext& context, const TrackingConfig& config,
                                     Map* map);

}  // namespace dslam
