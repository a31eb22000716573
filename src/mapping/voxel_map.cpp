#include "dslam/mapping/voxel_map.h"

#include <cmath>
#include <limits>

namespace dslam {
namespace {

constexpr uint16_t kMaxVotes = std::numeric_limits<uint16_t>::max();

int32_t Index(float coordinate_m, double voxel_size_m) {
  return static_cast<int32_t>(std::floor(coordinate_m / voxel_size_m));
}

}  // namespace

VoxelMap::Key VoxelMap::KeyOf(const Eigen::Vector3f& p_world) const {
  return {Index(p_world.x(), voxel_size_m_), Index(p_world.y(), voxel_size_m_),
          Index(p_world.z(), voxel_size_m_)};
}

void VoxelMap::Add(const ColouredPoint& point_world, int keyframe_id) {
  Voxel& voxel = voxels_[KeyOf(point_world.p)];
  ++voxel.count;
  voxel.mean += (point_world.p - voxel.mean) / static_cast<float>(voxel.count);
  voxel.r += point_world.r;
  voxel.g += point_world.g;
  voxel.b += point_world.b;
  if (voxel.last_keyframe != keyframe_id && voxel.hits < kMaxVotes) ++voxel.hits;
  voxel.last_keyframe = keyframe_id;
}

size_t VoxelMap::Carve(const DepthView& view, const FreeSpaceTolerance& tolerance,
                       int oldest_keyframe) {
  size_t removed = 0;
  for (auto it = voxels_.begin(); it != voxels_.end();) {
    Voxel& voxel = it->second;
    if (voxel.last_keyframe >= oldest_keyframe &&
        view.Vote(voxel.mean, tolerance) == Visibility::kSeeThrough && voxel.misses < kMaxVotes) {
      ++voxel.misses;
    }
    if (tolerance.Transient(voxel.misses, voxel.hits)) {
      it = voxels_.erase(it);
      ++removed;
    } else {
      ++it;
    }
  }
  return removed;
}

size_t VoxelMap::Crop(const Eigen::Vector3f& centre_world, double half_side_m) {
  size_t removed = 0;
  for (auto it = voxels_.begin(); it != voxels_.end();) {
    if ((it->second.mean - centre_world).cwiseAbs().maxCoeff() > half_side_m) {
      it = voxels_.erase(it);
      ++removed;
    } else {
      ++it;
    }
  }
  return removed;
}

ColouredCloud VoxelMap::Points() const {
  ColouredCloud cloud;
  cloud.reserve(voxels_.size());
  for (const auto& entry : voxels_) {
    const Voxel& voxel = entry.second;
    const auto mean = [&voxel](uint32_t sum) {
      return static_cast<uint8_t>((sum + voxel.count / 2) / voxel.count);
    };
    cloud.push_back({voxel.mean, mean(voxel.r), mean(voxel.g), mean(voxel.b)});
  }
  return cloud;
}

}  // namespace dslam
