#pragma once
// The static map's store: a hash grid of voxels in the world frame, each holding one point (the
// running mean of the points fused into it and their mean colour) and the votes of the
// free-space check: hits (keyframes that fused a point into it) and misses (keyframes that saw
// through it).
//
// Cost per keyframe independent of the map's size: Carve visits only the voxels hit by the
// keyframes it votes for (kept in buckets by keyframe id), and Crop walks the voxels only when
// the bounding box of every point fused since its last walk leaves the cube it keeps. Both give
// the voxels a walk over every voxel gives (test/mapping/voxel_map_test.cpp).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <unordered_map>
#include <vector>

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
  /// (FreeSpaceTolerance::Transient) are removed. Returns the number removed. Only the voxels
  /// voted on can become transient (a voxel is made with a hit and no miss, and a hit never
  /// makes one transient), so only they are visited; an `oldest_keyframe` below an earlier
  /// call's (ids not growing) walks every voxel.
  size_t Carve(const DepthView& view, const FreeSpaceTolerance& tolerance, int oldest_keyframe);

  /// Removes the voxels whose point lies outside the axis-aligned cube of half-side
  /// `half_side_m` [m] centred on `centre_world` [m]. Returns the number removed.
  size_t Crop(const Eigen::Vector3f& centre_world, double half_side_m);

  bool Contains(const Key& key) const { return voxels_.count(key) > 0; }
  /// One point per voxel (mean position and colour), in the world frame; order unspecified.
  ColouredCloud Points() const;
  size_t size() const { return voxels_.size(); }  ///< number of voxels
  void Clear();

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

  /// Votes of `view` on `voxel` and whether it became transient (Carve's test of one voxel).
  static bool VoteAndTest(const DepthView& view, const FreeSpaceTolerance& tolerance, Voxel* voxel);
  size_t CarveAll(const DepthView& view, const FreeSpaceTolerance& tolerance, int oldest_keyframe);

  double voxel_size_m_;
  std::unordered_map<Key, Voxel, KeyHash> voxels_;
  /// Keyframe id -> the voxels whose last_keyframe became that id (a voxel hit again later is
  /// listed under its newer keyframe too; the older entry is skipped). Buckets below
  /// `dropped_below_` were dropped.
  std::map<int, std::vector<Key>> hit_by_keyframe_;
  int dropped_below_ = std::numeric_limits<int>::min();
  /// [m] a box holding every voxel's point: grown by each point fused, made tight by Crop's walk.
  Eigen::Vector3f box_min_ = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector3f box_max_ = Eigen::Vector3f::Constant(std::numeric_limits<float>::lowest());
};

}  // namespace dslam
