#pragma once
// Votes of keyframes' rays on map points, from the rays alone (GridView: a camera centre and the
// points its static depth measured), for the occupancy grid (BuildOccupancyGrid): a view whose
// nearest surface around a point's direction lies beyond the point saw through it; a view that
// measured a surface at the point's range measured it.

#include <vector>

#include <Eigen/Core>

#include "dslam/core/config.h"
#include "dslam/mapping/free_space.h"
#include "dslam/mapping/occupancy_grid.h"

namespace dslam {

/// The margins of the votes.
struct ViewVoteTolerance {
  /// Misses: the static map's free-space margins and depth range (map.free_space_margin_m,
  /// free_space_margin_ratio; depth_noise.min/max_depth_m), and Transient's rule.
  FreeSpaceTolerance see_through;
  /// Measured: a range within HitMargin of the point's.
  DepthNoiseConfig depth_noise;
  double voxel_size_m = 0.05;  ///< [m] the static map's voxel (its points are voxel centroids)

  /// The tolerances of `config` (its map and depth_noise sections).
  static ViewVoteTolerance From(const Config& config);
  /// [m] half a voxel plus twice the depth noise at `range_m` [m] (DepthSigma): a surface measured
  /// this close to a point measured the point.
  double HitMargin(double range_m) const;
};

/// What the views said of one point.
struct RayVotes {
  int hits = 0;      ///< views with a surface at the point (within see_through's margin)
  int measured = 0;  ///< of those, views with the surface within HitMargin of the point
  int misses = 0;    ///< views whose nearest surface around the point's direction lies beyond it
};

/// The votes of `views` on each of `points_world` [m, world frame]. Each view's points are
/// binned by direction from its camera on a cube map of `bin_rad` [rad] bins (the nearest range
/// per bin). A view misses a point at range r when the nearest range in the 3x3 bins around the
/// point's direction exceeds r by more than see_through's margin (margin_m + margin_ratio r),
/// hits it when the point's own bin holds a range within that margin of r, and measured it when
/// that range lies within HitMargin(r) of r (a tighter margin, from the depth noise); points outside
/// see_through's range [min_depth_m, max_depth_m] from the camera, and directions without a
/// measured bin around them, get no vote.
std::vector<RayVotes> VoteByViews(const std::vector<Eigen::Vector3f>& points_world,
                                  const std::vector<GridView>& views,
                                  const ViewVoteTolerance& tolerance, double bin_rad);

}  // namespace dslam
