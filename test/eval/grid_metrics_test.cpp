// The grid's scores with known answers: a 10 x 10 grid of 0.1 m cells whose frame is the world's
// (z up, floor at 0, band 0.1-2 m), a static wall along x = 0.55 and a person's path along
// y = 0.55; occupied cells on the wall, one beside it (within a cell: precise), one far from it
// and one on the person's path.
#include <vector>

#include <gtest/gtest.h>

#include "dslam/eval/grid_metrics.h"

namespace dslam {
namespace {

OccupancyGrid EmptyGrid() {
  OccupancyGrid grid;
  grid.cell_size_m = 0.1;
  grid.width = grid.height = 10;
  grid.min_height_m = 0.1;
  grid.max_height_m = 2.0;
  grid.cells.assign(100, kCellUnknown);
  return grid;
}

void Occupy(OccupancyGrid* grid, int i, int j) { grid->cells[j * grid->width + i] = kCellOccupied; }

MapReference Reference() {
  MapReference reference;
  for (int j = 0; j < 10; ++j) {
    reference.static_points.emplace_back(0.55, 0.1 * j + 0.05, 1.0);  // the wall, column 5
    reference.static_points.emplace_back(0.55, 0.1 * j + 0.05, 3.0);  // above the band: no cell
  }
  for (int i = 0; i < 10; ++i) reference.dynamic_points.emplace_back(0.1 * i + 0.05, 0.55, 1.0);
  return reference;
}

TEST(GridMetrics, PrecisionRecallAndGhostCells) {
  OccupancyGrid grid = EmptyGrid();
  for (int j = 0; j < 10; ++j) Occupy(&grid, 5, j);  // the wall: all ten cells
  Occupy(&grid, 6, 2);                               // beside the wall: within a cell
  Occupy(&grid, 9, 9);                               // far from everything
  Occupy(&grid, 1, 5);                               // on the path, far from the wall: a ghost
  const GridMetrics m = EvaluateGrid(grid, Eigen::Isometry3d::Identity(), Reference());
  EXPECT_EQ(m.occupied_cells, 13u);
  EXPECT_EQ(m.static_truth_cells, 10u);
  // Path cells with no wall cell within one: columns 0-3 and 7-9 (4, 5 and 6 touch the wall).
  EXPECT_EQ(m.people_truth_cells, 7u);
  EXPECT_EQ(m.ghost_cells, 1u);
  EXPECT_DOUBLE_EQ(m.precision, 11.0 / 13.0);
  EXPECT_DOUBLE_EQ(m.recall, 1.0);
}

TEST(GridMetrics, PointsScoredAsOccupiedCellsAndTheGridPlaced) {
  // The grid's world is the truth's shifted by 1 m in x: T_truth_world moves it back.
  OccupancyGrid grid = EmptyGrid();
  Eigen::Isometry3d T_truth_world = Eigen::Isometry3d::Identity();
  T_truth_world.translation().x() = 1.0;
  grid.T_world_grid.translation().x() = -1.0;
  std::vector<Eigen::Vector3d> points;  // in the truth world: half the wall and a ghost
  for (int j = 0; j < 5; ++j) points.emplace_back(0.55, 0.1 * j + 0.05, 0.5);
  points.emplace_back(0.15, 0.55, 0.5);
  points.emplace_back(0.15, 0.55, 2.5);  // above the band
  const GridMetrics m = EvaluateOccupiedPoints(grid, T_truth_world, points, Reference());
  EXPECT_EQ(m.occupied_cells, 6u);
  EXPECT_EQ(m.ghost_cells, 1u);
  EXPECT_DOUBLE_EQ(m.recall, 0.6);  // wall rows 0-5 are within a cell of rows 0-4
  EXPECT_DOUBLE_EQ(m.precision, 5.0 / 6.0);
}

}  // namespace
}  // namespace dslam
