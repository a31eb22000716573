#pragma once
// The static map as an OctoMap (octomap::OcTree, Debian's liboctomap), written as the binary .bt
// file octovis and octomap_server read. OctoMap's headers stay in octomap_file.cpp.

#include <string>

#include "dslam/mapping/static_mapper.h"

namespace dslam {

/// Counts of a written OctoMap.
struct OctoMapStats {
  size_t occupied_leaves = 0;  ///< leaves whose occupancy is above OctoMap's threshold (0.5)
  size_t free_leaves = 0;      ///< the other known leaves
};

/// Writes `rays` (StaticMapper::Rays: world frame) as an OcTree of `resolution_m` [m] leaves to
/// `path` (OcTree::writeBinary, maximum-likelihood, pruned): each view's points inserted as hits
/// with misses along the rays from its camera (OcTree::insertPointCloud, discretized), then each
/// point of the map fused for good as one more hit (keyframes the mapper no longer keeps gave
/// them: they have no rays). The people are in neither: their pixels are never fused. Throws
/// std::runtime_error naming `path` when it cannot be written.
OctoMapStats WriteOctoMap(const StaticMapRays& rays, double resolution_m, const std::string& path);

}  // namespace dslam
