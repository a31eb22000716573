#pragma once
// The static map's store: a hash grid of voxels in the world frame, each holding one point (the
// running mean of the points fused into it and their mean colour) and the votes of the
// free-space check: hits (keyframes that fused a point into it) and misses (keyframes that saw
// through it).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <unordered_map>

#include <Eigen/Core>

#include "dslam/mapping/coloured_cloud.h"
#include "dslam/mapping/free_space.h"

namespace dslam {

/// Voxels of a fixed edge; not thread-safe (the StaticMapper guards it).
class VoxelMap {
 public:
  /// Integer coordinates of a voxel: floor(p / voxel_size_m) per axis.
  struct Key {
    int32_t x, y, z;
    bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
  };

  /// `voxel_size_m` > 0 [m].
  explicit VoxelMap(double voxel_size_m) : voxel_size_m_(voxel_size_m) {}

  /// The voxel holding `p_world` [m].
  Key KeyOf(const Eigen::Vector3f& p_world) const;

  /// Fuses one point of keyframe `keyframe_id` into its voxel: a keyframe counts one hit per
  /// voxel however many of its points fall into it (call with its points one after another).
  void Add(const ColouredPoint& point_world, int keyframe_id);

  /// The point of each voxel last hit by keyframe `oldest_keyframe` or a later one (ids grow with
  /// time) voted on by `view`: a see-through adds a miss; voxels that become transient
  /// (FreeSpaceTolerance::Transient) are removed. Returns the number removed.
  size_t Carve(const DepthView& view, const FreeSpaceTolerance& tolerance, int oldest_keyframe);

  /// Removes the voxels whose point lies outside the axis-aligned cube of half-side
  /// `half_side_m` [m] centred on `centre_world` [m]. Returns the number removed.
  size_t Crop(const Eigen::Vector3f& centre_world, double half_side_m);

  bool Contains(const Key& key) const { return voxels_.count(key) > 0; }
  /// One point per voxel (mean position and colour), in the world frame; order unspecified.
  ColouredCloud Points() const;
  size_t size() const { return voxels_.size(); }  ///< number of voxels
  void Clear() { voxels_.clear(); }

 private:
  struct KeyHash {
    size_t operator()(const Key& k) const {
      // Three large odd multipliers (Teschner et al. 2003, spatial hashing).
      return (static_cast<size_t>(static_cast<uint32_t>(k.x)) * 73856093u) ^
             (static_cast<size_t>(static_cast<uint32_t>(k.y)) * 19349663u) ^
             (static_cast<size_t>(static_cast<uint32_t>(k.z)) * 83492791u);
    }
  };
  struct Voxel {
    Eigen::Vector3f mean = Eigen::Vector3f::Zero();  ///< [m] running mean of the points
    uint32_t r = 0, g = 0, b = 0;                    ///< colour sums
    uint32_t count = 0;                              ///< points fused
    uint16_t hits = 0, misses = 0;                   ///< keyframes (saturating)
    int last_keyframe = -1;                          ///< the keyframe of the last point
  };

  double voxel_size_m_;
  std::unordered_map<Key, Voxel, KeyHash> voxels_;
};

}  // namespace dslam
