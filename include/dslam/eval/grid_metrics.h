#pragma once
// An occupancy grid (dslam/mapping/occupancy_grid.h) against synthetic truth (MapReference,
// map_metrics.h): the truth's static points and the places of moving objects, projected into the
// grid's cells within its height band, give the cells the static world occupies and the cells
// people stood in. A cell matches another within one cell (8-neighbourhood): a pose error of half
// a cell must not count as a miss.
// - precision: occupied cells within one cell of a static truth cell / occupied cells;
// - recall: static truth cells within one cell of an occupied cell / static truth cells;
// - ghost cells: occupied cells where only people stood (a moving-object truth cell with no
//   static truth cell within one cell).

#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "dslam/eval/map_metrics.h"
#include "dslam/mapping/occupancy_grid.h"

namespace dslam {

/// Scores of a grid.
struct GridMetrics {
  size_t occupied_cells = 0;
  size_t static_truth_cells = 0;  ///< cells the static truth occupies in the band
  size_t people_truth_cells = 0;  ///< cells moving objects occupied in the band, no static one near
  size_t ghost_cells = 0;         ///< occupied cells among people_truth_cells
  double precision = 0.0;         ///< 0 without occupied cells
  double recall = 0.0;            ///< 0 without static truth cells
};

/// Scores `grid` against `reference` (truth world frame); `T_truth_world` places the grid's world
/// (the run's world frame) in the truth's.
GridMetrics EvaluateGrid(const OccupancyGrid& grid, const Eigen::Isometry3d& T_truth_world,
                         const MapReference& reference);

/// Occupied cells that points in the grid's band make, in the grid's cell indexing (cells outside
/// the grid included): the grid a map without masks and rays gives (`points` in the truth world,
/// placed by `T_truth_world` as for EvaluateGrid); scored like a grid's occupied cells.
GridMetrics EvaluateOccupiedPoints(const OccupancyGrid& grid,
                                   const Eigen::Isometry3d& T_truth_world,
                                   const std::vector<Eigen::Vector3d>& points,
                                   const MapReference& reference);

}  // namespace dslam
