#pragma once
// Config section `map`: the static map (part `mapping`): each keyframe's depth fused into a voxel
// map in the odometry (world) frame, without the pixels of moving objects and without points
// that other keyframes see through. A member of the one Config tree (config.h).

#include "dslam/core/config_field.h"

namespace dslam {

/// Static map fusion (dslam/mapping/static_mapper.h). Units, ranges and meanings of the fields
/// are given in Fields() (printed by `dslam_config_doc`).
struct MapConfig {
  bool enabled = true;
  double voxel_size_m = 0.05;
  double extent_m = 10.0;
  int pixel_step = 4;
  double max_depth_m = 4.0;
  bool dynamic_masks = true;
  int mask_radius_px = 25;
  bool free_space_check = true;
  int free_space_keyframes = 30;
  double free_space_margin_m = 0.1;
  double free_space_margin_ratio = 0.03;
  int free_space_min_misses = 1;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    // The ROS node's switch (static_map, save_map); dslam_run_dataset fuses when --map is given.
    v(Flag("enabled", "fuse keyframes into the static map"), s.enabled);
    // Memory: a voxel holds one point (position and colour sums, counts), about 60 bytes in the
    // hash map; a surface of A m^2 takes A / voxel_size_m^2 voxels.
    v(Field("voxel_size_m", "m", 0.005, 1.0, "edge of a map voxel (one point per voxel)"),
      s.voxel_size_m);
    // The memory bound: whatever lies outside the cube is dropped as keyframes are fused.
    v(Field("extent_m", "m", 0.1, 10000.0,
            "the map keeps the cube of this half-side around the newest fused keyframe's camera"),
      s.extent_m);
    v(Field("pixel_step", "px", 1, 64, "keyframe depth is sampled every pixel_step pixels"),
      s.pixel_step);
    v(Field("max_depth_m", "m", 0.1, 100.0,
            "depths beyond are neither fused nor used by the free-space check"),
      s.max_depth_m);
    // Off: every pixel with depth is fused (the static-world baseline, with free_space_check off).
    v(Flag("dynamic_masks", "leave out the pixels of moving objects (keyframe_mask.h)"),
      s.dynamic_masks);
    v(Field("mask_radius_px", "px", 0, 1000, "disc masked around each unmarked point"),
      s.mask_radius_px);
    // A point is transient when keyframes see through it (their depth along its ray is beyond it
    // by the margin) at least free_space_min_misses times and at least as often as keyframes saw
    // a surface there (free_space.h).
    v(Flag("free_space_check", "remove points other keyframes see through"), s.free_space_check);
    v(Field("free_space_keyframes", "-", 1, 1000,
            "fused keyframes whose depth images check a keyframe's points as it is fused"),
      s.free_space_keyframes);
    v(Field("free_space_margin_m", "m", 0.0, 10.0,
            "depth beyond a point by more than margin_m + margin_ratio x depth sees through it"),
      s.free_space_margin_m);
    v(Field("free_space_margin_ratio", "-", 0.0, 1.0, "the margin's share of the depth"),
      s.free_space_margin_ratio);
    v(Field("free_space_min_misses", "-", 1, 1000,
            "keyframes that must see through a point before it is removed"),
      s.free_space_min_misses);
  }
};

}  // namespace dslam
