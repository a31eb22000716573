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
  bool dynamic_masks = true;
  bool free_space_check = true;
  int free_space_keyframes = 30;
  double free_space_margin_m = 0.05;
  double free_space_margin_ratio = 0.02;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    // The ROS node's switch (static_map, save_map); dslam_run_dataset fuses when --map is given.
    v(Flag("enabled", "fuse keyframes into the static map"), s.enabled);
    // Memory: a surface of A m^2 takes about A / voxel_size_m^2 voxels, each about 92 bytes (the
    // docs/how-it-works.md's Static map section has the measurement).
    v(Field("voxel_size_m", "m", 0.005, 1.0, "edge of a map voxel (one point per voxel)"),
      s.voxel_size_m);
    // The memory bound: whatever lies outside the cube is dropped as keyframes are fused.
    v(Field("extent_m", "m", 0.1, 10000.0,
            "the map keeps the cube of this half-side around the newest fused keyframe's camera"),
      s.extent_m);
    v(Field("pixel_step", "px", 1, 64, "keyframe depth is sampled every pixel_step pixels"),
      s.pixel_step);
    // Off: every pixel with depth is fused (the static-world baseline, with free_space_check off).
    // The mask grows from the keyframe's unmarked points (section dynamic_mask).
    v(Flag("dynamic_masks", "leave out the pixels of moving objects (dynamic_mask.h)"),
      s.dynamic_masks);
    // A point is transient when keyframes see through it (their depth along its ray is beyond it
    // by the margin) at least once and at least as often as keyframes saw a surface there
    // (free_space.h).
    v(Flag("free_space_check", "remove points other keyframes see through"), s.free_space_check);
    // Also the reach in time of the check: keyframes farther apart than this never vote on each
    // other's points (their drift would make static surfaces look seen through).
    v(Field("free_space_keyframes", "-", 1, 1000,
            "keyframes before a fused keyframe whose depth checks its points, and whose points "
            "its depth checks"),
      s.free_space_keyframes);
    v(Field("free_space_margin_m", "m", 0.0, 10.0,
            "depth beyond a point by more than margin_m + margin_ratio x depth sees through it"),
      s.free_space_margin_m);
    v(Field("free_space_margin_ratio", "-", 0.0, 1.0, "the margin's share of the depth"),
      s.free_space_margin_ratio);
  }
};

}  // namespace dslam
