#pragma once
// The one Config tree of dslam: every tunable value with its default and unit. Sections are plain
// structs; each lists its fields once in Fields(), which drives Validate(), the YAML and rosparam
// loaders and the generated parameter documentation (dslam_config_doc). Each area's sections
// live in their own small header so that modules include only what they use.

#include <string>

#include "dslam/core/backend_config.h"
#include "dslam/core/config_field.h"
#include "dslam/core/features_config.h"
#include "dslam/core/grid_config.h"
#include "dslam/core/loop_closing_config.h"
#include "dslam/core/map_config.h"
#include "dslam/core/objects_config.h"
#include "dslam/core/static_points_config.h"
#include "dslam/core/tracking_config.h"

namespace dslam {

/// Reading TUM-layout folders (rgb.txt, depth.txt, groundtruth.txt). Units, ranges and meanings
/// of the fields are given in Fields() (printed by `dslam_config_doc`).
struct DatasetConfig {
  double association_max_dt_s = 0.02;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    v(Field("association_max_dt_s", "s", 0.0, 1.0,
            "max colour/depth timestamp difference for association"),
      s.association_max_dt_s);
  }
};

/// Root of the configuration. Add a section: a member, a line in Sections(), and its Fields().
struct Config {
  DatasetConfig dataset;             ///< dataset reading
  DepthNoiseConfig depth_noise;      ///< RGB-D point measurement noise (features_config.h)
  FeaturesConfig features;           ///< ORB extraction (features_config.h)
  PoseConfig pose;                   ///< motion-only BA and RANSAC (features_config.h)
  StaticPointsConfig static_points;  ///< static point determination (static_points_config.h)
  TrackingConfig tracking;           ///< local map, keyframes, recovery (tracking_config.h)
  BackendConfig backend;             ///< local mapping after keyframes (backend_config.h)
  LoopClosingConfig loop_closing;    ///< loops over the keyframe map (loop_closing_config.h)
  DynamicMaskConfig dynamic_mask;    ///< per-pixel masks of moving things (objects_config.h)
  ObjectsConfig objects;             ///< moving objects tracked across frames (objects_config.h)
  MapConfig map;                     ///< the static map (map_config.h)
  GridConfig grid;                   ///< occupancy grid from the static map (grid_config.h)

  /// Calls `f(name, section)` for every section, in documentation order.
  template <typename Self, typename F>
  static void Sections(Self& s, F&& f) {
    f("dataset", s.dataset);
    f("depth_noise", s.depth_noise);
    f("features", s.features);
    f("pose", s.pose);
    f("static_points", s.static_points);
    f("tracking", s.tracking);
    f("backend", s.backend);
    f("loop_closing", s.loop_closing);
    f("dynamic_mask", s.dynamic_mask);
    f("objects", s.objects);
    f("map", s.map);
    f("grid", s.grid);
  }

  /// Throws ConfigError naming the first out-of-range or inconsistent parameter.
  void Validate() const;
};

}  // namespace dslam
