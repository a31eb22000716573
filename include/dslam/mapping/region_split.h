#pragma once
// Splitting a dynamic-mask region that holds two moving things at different velocities (two
// people walking side by side, one of them pausing): single-linkage clustering joins them when
// their points come closer than DynamicMaskConfig::cluster_distance_m.
//
// Steps (SplitRegions), per region:
// 0. Two tracked objects whose predicted positions lie in the region's box, at least
//    ObjectsConfig::split_min_distance_m apart, give the two centres to split around (two people
//    who walked side by side and then stopped: their velocities no longer differ). When there
//    are none, or their parts fail step 5:
// 1. The velocity of each of its points over ObjectsConfig::motion_baseline_s (PointVelocity).
// 2. Two-means of those velocities, started from the 10th and 90th percentiles along their
//    principal axis.
// 3. When both groups have at least kSplitMinPoints points and their per-axis
//    median velocities differ by at least ObjectsConfig::split_speed_mps (the points of one rigid
//    thing differ by noise only), the groups' per-axis median positions are the two centres.
// 4. The region's cells are shared out by two-means of their points' positions across the view
//    (optical x and depth, not the image's vertical), started from the two centres; every point
//    goes with its cell (a point without a cell of the region: with the nearer part's mean).
// 5. The split is kept when the two parts stand side by side: each holds kSplitMinPoints of the
//    region's points, their cells' horizontal ranges (10th-90th percentile of optical x) overlap
//    by at most ObjectsConfig::split_max_overlap of the narrower range, and their mean positions
//    across the view are at least split_min_distance_m apart. A leg moving unlike the body above
//    it gives two centres one above the other: the parts across the view are then two halves of
//    one body, closer than a body's width. (A part lies on one side of a cut across the view, so
//    the overlap only refuses parts at different depths; a single moving thing wider than about
//    twice split_min_distance_m whose points move differently would be split.)
// Both parts are split again, up to kMaxSplitParts parts per region.
//
// Why the parts and not the point groups are tested: a second person emerging beside a nearer
// one has few points, often near the border of the two, and velocities noisy enough that some
// land in the other group; the groups' median positions can then lie closer than a body's width
// while the two bodies' cells do not (measured on the synthetic walking scenarios,
// docs/benchmarks/mapping.md, "Regions split across the view").

#include <deque>

#include <Eigen/Geometry>

#include "dslam/core/objects_config.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/mapping/dynamic_mask.h"
#include "dslam/mapping/object_tracker.h"

namespace dslam {

/// Most parts one region is split into.
constexpr int kMaxSplitParts = 4;
/// Points with a velocity each of the two groups and each split part needs.
constexpr int kSplitMinPoints = 5;

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
