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
  const Key key = KeyOf(point_world.p);
  Voxel& voxel = voxels_[key];
  ++voxel.count;
  voxel.mean += (point_world.p - voxel.mean) / static_cast<float>(voxel.count);
  voxel.r += point_world.r;
  voxel.g += point_world.g;
  voxel.b += point_world.b;
  if (voxel.last_keyframe != keyframe_id) {
    if (voxel.hits < kMaxVotes) ++voxel.hits;
    hit_by_keyframe_[keyframe_id].push_back(key);
  }
  voxel.last_keyframe = keyframe_id;
  box_min_ = box_min_.cwiseMin(voxel.mean);
  box_max_ = box_max_.cwiseMax(voxel.mean);
}

void VoxelMap::Clear() {
  voxels_.clear();
  hit_by_keyframe_.clear();
  dropped_below_ = std::numeric_limits<int>::min();
  box_min_ = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  box_max_ = Eigen::Vector3f::Constant(std::numeric_limits<float>::lowest());
}

bool VoxelMap::VoteAndTest(const DepthView& view, const FreeSpaceTolerance& tolerance,
                           Voxel* voxel) {
  if (view.Vote(voxel->mean, tolerance) == Visibility::kSeeThrough && voxel->misses < kMaxVotes) {
    ++voxel->misses;
  }
  return tolerance.Transient(voxel->misses, voxel->hits);
}

size_t VoxelMap::Carve(const DepthView& view, const FreeSpaceTolerance& tolerance,
                       int oldest_keyframe) {
  if (oldest_keyframe < dropped_below_) return CarveAll(view, tolerance, oldest_keyframe);
  size_t removed = 0;
  for (auto bucket = hit_by_keyframe_.lower_bound(oldest_keyframe);
       bucket != hit_by_keyframe_.end(); ++bucket) {
    for (const Key& key : bucket->second) {
      const auto it = voxels_.find(key);
      // Erased, or hit again by a newer keyframe (its newer bucket votes for it).
      if (it == voxels_.end() || it->second.last_keyframe != bucket->first) continue;
      if (!VoteAndTest(view, tolerance, &it->second)) continue;
      voxels_.erase(it);
      ++removed;
    }
  }
  hit_by_keyframe_.erase(hit_by_keyframe_.begin(), hit_by_keyframe_.lower_bound(oldest_keyframe));
  dropped_below_ = oldest_keyframe;
  return removed;
}

size_t VoxelMap::CarveAll(const DepthView& view, const FreeSpaceTolerance& tolerance,
                          int oldest_keyframe) {
  size_t removed = 0;
  for (auto it = voxels_.begin(); it != voxels_.end();) {
    Voxel& voxel = it->second;
    const bool transient = voxel.last_keyframe >= oldest_keyframe
                               ? VoteAndTest(view, tolerance, &voxel)
                               : tolerance.Transient(voxel.misses, voxel.hits);
    if (transient) {
      it = voxels_.erase(it);
      ++removed;
    } else {
      ++it;
    }
  }
  return removed;
}

size_t VoxelMap::Crop(const Eigen::Vector3f& centre_world, double half_side_m) {
  const auto inside = [&](const Eigen::Vector3f& p) {
    return (p - centre_world).cwiseAbs().maxCoeff() <= half_side_m;
  };
  if (voxels_.empty() || (inside(box_min_) && inside(box_max_))) return 0;  // the box is inside
  size_t removed = 0;
  box_min_ = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  box_max_ = Eigen::Vector3f::Constant(std::numeric_limits<float>::lowest());
  for (auto it = voxels_.begin(); it != voxels_.end();) {
    if (!inside(it->second.mean)) {
      it = voxels_.erase(it);
      ++removed;
    } else {
      box_min_ = box_min_.cwiseMin(it->second.mean);
      box_max_ = box_max_.cwiseMax(it->second.mean);
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
