#include "dslam/mapping/octomap_file.h"

#include <stdexcept>

#include <octomap/OcTree.h>

namespace dslam {

OctoMapStats WriteOctoMap(const StaticMapRays& rays, double resolution_m,
                          const std::string& path) {
  if (!(resolution_m > 0.0)) throw std::invalid_argument("WriteOctoMap: resolution <= 0");
  octomap::OcTree tree(resolution_m);
  for (const GridView& view : rays.views) {
    octomap::Pointcloud cloud;
    cloud.reserve(view.points_world.size());
    for (const Eigen::Vector3f& p : view.points_world) cloud.push_back(p.x(), p.y(), p.z());
    const octomap::point3d origin(static_cast<float>(view.camera_world.x()),
                                  static_cast<float>(view.camera_world.y()),
                                  static_cast<float>(view.camera_world.z()));
    tree.insertPointCloud(cloud, origin, /*maxrange=*/-1.0, /*lazy_eval=*/true,
                          /*discretize=*/true);
  }
  for (const Eigen::Vector3f& p : rays.points_world) {
    tree.updateNode(octomap::point3d(p.x(), p.y(), p.z()), true, /*lazy_eval=*/true);
  }
  tree.updateInnerOccupancy();
  tree.prune();
  OctoMapStats stats;
  for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it) {
    if (tree.isNodeOccupied(*it)) {
      ++stats.occupied_leaves;
    } else {
      ++stats.free_leaves;
    }
  }
  if (!tree.writeBinary(path)) throw std::runtime_error("cannot write the OctoMap " + path);
  return stats;
}

}  // namespace dslam
