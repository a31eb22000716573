#pragma once
// Splitting a dynamic-mask region that holds two moving things at different velocities (two
// people walking side by side, one of them pausing): single-linkage clustering joins them when
// their points come closer than DynamicMaskConfig::cluster_distance_m.
//
// Steps (SplitRegions), per region:
// 0. Two tracked objects whose predicted positions lie in the region's box, at least
//    ObjectsConfig::split_min_distance_m apart, split it by the nearer prediction of each point
//    (two people who walked side by side and then stopped: their velocities no longer differ).
//    Otherwise:
// 1. The velocity of each of its points over ObjectsConfig::motion_baseline_s (PointVelocity).
// 2. Two-means of those velocities, started from the 10th and 90th percentiles along their
//    principal axis.
// 3. The split is kept when both groups have at least ObjectsConfig::split_min_points points and
//    their per-axis median velocities differ by at least ObjectsConfig::split_speed_mps: the
//    points of one rigid thing differ by noise only.
// 4. The region's cells are shared out by a breadth-first growth over the region's cells from
//    both groups' seed cells at once (each cell goes to the group whose points are nearer along
//    the region); points without a velocity go with their cell. Both parts are split again,
//    up to kMaxSplitParts parts per region.

#include <deque>

#include <Eigen/Geometry>

#include "dslam/core/objects_config.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/mapping/dynamic_mask.h"
#include "dslam/mapping/object_tracker.h"

namespace dslam {

/// Most parts one region is split into.
constexpr int kMaxSplitParts = 4;

/// Splits the regions of `mask` (computed from `frame` at `T_world_camera` with `mask_config`)
/// that hold two moving things: two of the `predicted` positions [m, world] of the tracks (at
/// least ObjectsConfig::split_min_distance_m apart) inside a region's box, or (else) two groups of
/// point velocities taken from `history` (recent frames' PositionsOf, oldest first) at `stamp_s`
/// [s]. New regions are appended (labels continue); the statistics of split regions are
/// recomputed. Returns the number of splits.
int SplitRegions(const RgbdFrame& frame, const Eigen::Isometry3d& T_world_camera,
                 const std::deque<PointPositions>& history, double stamp_s,
                 const std::vector<Eigen::Vector3d>& predicted,
                 const DynamicMaskConfig& mask_config, const ObjectsConfig& objects_config,
                 DynamicMask* mask);

}  // namespace dslam
