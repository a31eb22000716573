#pragma once
// Per-pixel mask of the moving things in one frame, grown from the frame's unmarked points over
// its depth image. The static point determination labels sparse points; the static map and the
// moving objects need the pixels between them.
//
// Steps (ComputeDynamicMask):
// 1. Each unmarked matched point is measured again in this frame (its map position is stale: the
//    thing moved since the point was made): the depth at its pixel, back-projected.
// 2. Single-linkage clustering in 3D (DynamicMaskConfig::cluster_distance_m); clusters whose
//    boxes come closer than margin_m are merged (one person's sparse points split by single
//    linkage); clusters with fewer than min_cluster_points points are left out.
// 3. Each cluster grows over a grid of cells (every decimation-th pixel) from its points' cells to
//    4-neighbours whose depth is continuous (|dz| <= depth_step_m + depth_step_ratio * z) and
//    whose 3D point lies within margin_m of the cluster's box. Cells of verified static points
//    are never entered; a cell belongs to the first region that reaches it. A region that meets
//    an earlier one across a depth-continuous border is merged into it (one surface, one thing).
// 4. With a DepthReference (depth_change.h): the cells (not blocked, not yet labelled) nearer than
//    a recent frame saw along their ray, in 4-connected depth-continuous groups of at least
//    depth_change_min_cells, grow regions as in 3 (box: the group's cells). A region that meets
//    an earlier one, or whose world box comes within margin_m of an earlier region's box (a limb
//    or the head of a person whose body the points seeded), is merged into it. The matched points
//    not verified static (unmarked, or candidates) in the cells of the new regions this step
//    keeps join them as their points, measured as in 1.

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/core/objects_config.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/mapping/depth_change.h"
#include "dslam/tracking/frame_result.h"

namespace dslam {

/// One moving thing's region of a DynamicMask.
struct DynamicRegion {
  uint16_t label = 0;           ///< value of its cells in DynamicMask::labels (1-based)
  std::vector<PointId> points;  ///< the unmarked points that seeded it
  /// [m] those points measured in this frame (depth at their pixels), world frame; same order.
  std::vector<Eigen::Vector3d> points_world;
  /// The mask cell each of those points seeded (index row * cols + col), -1 when none; same order.
  std::vector<int> point_cells;
  int cells = 0;  ///< mask cells it covers
  /// [m] mean of its cells' back-projected points, world frame (the T_world_camera given).
  Eigen::Vector3d centroid_world = Eigen::Vector3d::Zero();
  Eigen::Vector3d min_world = Eigen::Vector3d::Zero();  ///< [m] axis-aligned box, world frame
  Eigen::Vector3d max_world = Eigen::Vector3d::Zero();  ///< [m] axis-aligned box, world frame
  /// [0, 1] mean colour of its cells (B, G, R; grey images: three equal channels).
  Eigen::Vector3d mean_colour = Eigen::Vector3d::Zero();
};

/// The mask of one frame: a label per cell of decimation x decimation pixels.
struct DynamicMask {
  int decimation = 1;  ///< [px] cell side
  /// CV_16UC1, (rows / decimation) x (cols / decimation): the region label of each cell,
  /// 0 = not on a moving thing. Cell (r, c) covers pixels [c*d, c*d+d) x [r*d, r*d+d).
  cv::Mat labels;
  std::vector<DynamicRegion> regions;  ///< regions[i].label == i + 1

  /// Cell index (row * cols + col) of pixel (u, v) of the full image [px]; -1 outside the grid.
  int CellAt(int u, int v) const;
  /// Label of pixel (u, v) of the full image [px]; 0 outside the grid.
  uint16_t LabelAt(int u, int v) const;
  /// Share [0, 1] of the grid's cells that are masked.
  double MaskedShare() const;
};

/// Computes the dynamic mask of `frame` from the matched points of its FrameResult (`points`,
/// with their labels at the end of the frame), with the frame's pose `T_world_camera` (optical
/// frame -> world) for the regions' world coordinates. Empty regions (and an all-zero mask) when
/// no cluster is large enough.
DynamicMask ComputeDynamicMask(const RgbdFrame& frame, const Eigen::Isometry3d& T_world_camera,
                               const std::vector<ObservedPoint>& points,
                               const DynamicMaskConfig& config);

/// As above, and clusters with fewer than min_cluster_points points but at least
/// `near_min_points` are kept when the mean of their points lies within `near_m` [m] of one of
/// `near_world` [m, world frame] (where tracked moving objects are expected: a tracked person
/// with few unmarked points in this frame). With `reference` (not null, not empty), regions are
/// also seeded by depth change (step 4 above).
DynamicMask ComputeDynamicMask(const RgbdFrame& frame, const Eigen::Isometry3d& T_world_camera,
                               const std::vector<ObservedPoint>& points,
                               const DynamicMaskConfig& config,
                               const std::vector<Eigen::Vector3d>& near_world, double near_m,
                               int near_min_points, const DepthReference* reference = nullptr);

}  // namespace dslam
