#pragma once
// Config section `grid`: the 2D occupancy grid made from the static map (part `mapping`,
// occupancy_grid.h): the static voxels in a height band above the floor are occupied, the rays
// of static depth through the band are free, the rest unknown. A member of the one Config tree
// (config.h).

#include "dslam/core/config_field.h"

namespace dslam {

/// Occupancy grid from the static map (dslam/mapping/occupancy_grid.h). Units, ranges and
/// meanings of the fields are given in Fields() (printed by `dslam_config_doc`).
struct GridConfig {
  double cell_size_m = 0.0;
  double min_height_m = 0.1;
  double max_height_m = 2.0;
  double floor_height_m = 1.2;
  double up_x = 0.0;
  double up_y = -1.0;
  double up_z = 0.0;
  double rate_hz = 1.0;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    v(Field("cell_size_m", "m", 0.0, 10.0, "edge of a grid cell; 0: the static map's voxel size"),
      s.cell_size_m);
    // The band a robot can hit: the floor (below min_height_m) and what lies above max_height_m
    // (a ceiling, a lamp) are not obstacles.
    v(Field("min_height_m", "m", -10.0, 10.0,
            "static map points at least this high above the floor are obstacles"),
      s.min_height_m);
    v(Field("max_height_m", "m", -10.0, 100.0,
            "static map points higher than this above the floor are not obstacles"),
      s.max_height_m);
    // Used when the static map shows no dominant horizontal plane below the first camera (a
    // floor it saw: FloorOf in occupancy_grid.h).
    v(Field("floor_height_m", "m", -100.0, 100.0,
            "height of the first camera above the floor when the map shows no floor"),
      s.floor_height_m);
    // Offline (dslam_run_dataset) the grid's up; the node takes its base_frame's z axis instead
    // when TF has the camera mount. The default is an optical frame's up: -y.
    v(Field("up_x", "-", -1.0, 1.0, "x of the up vector in the first camera's optical frame"),
      s.up_x);
    v(Field("up_y", "-", -1.0, 1.0, "y of the up vector in the first camera's optical frame"),
      s.up_y);
    v(Field("up_z", "-", -1.0, 1.0, "z of the up vector in the first camera's optical frame"),
      s.up_z);
    // The node also waits 9 times the last rebuild's time before the next (GridPublisher).
    v(Field("rate_hz", "Hz", 0.01, 100.0, "the node rebuilds the grid at most this often"),
      s.rate_hz);
  }
};

}  // namespace dslam
