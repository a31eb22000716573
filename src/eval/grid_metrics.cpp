#include "dslam/eval/grid_metrics.h"

#include <cstdint>
#include <unordered_set>

namespace dslam {
namespace {

using CellSet = std::unordered_set<uint64_t>;

uint64_t KeyOf(const Eigen::Vector2i& c) {
  return (static_cast<uint64_t>(static_cast<uint32_t>(c.x())) << 32) | static_cast<uint32_t>(c.y());
}

// The cells of `points_truth` within the grid's band.
CellSet CellsInBand(const OccupancyGrid& grid, const Eigen::Isometry3d& T_grid_truth,
                    const std::vector<Eigen::Vector3d>& points_truth) {
  CellSet cells;
  for (const Eigen::Vector3d& p : points_truth) {
    const Eigen::Vector3d g = T_grid_truth * p;
    if (g.z() < grid.min_height_m || g.z() > grid.max_height_m) continue;
    cells.insert(KeyOf(grid.CellOf(g.head<2>())));
  }
  return cells;
}

bool Near(const CellSet& cells, uint64_t key) {
  const int x = static_cast<int32_t>(key >> 32), y = static_cast<int32_t>(key & 0xffffffffu);
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if (cells.count(KeyOf({x + dx, y + dy}))) return true;
    }
  }
  return false;
}

GridMetrics Score(const CellSet& occupied, const OccupancyGrid& grid,
                  const Eigen::Isometry3d& T_grid_truth, const MapReference& reference) {
  const CellSet truth_static = CellsInBand(grid, T_grid_truth, reference.static_points);
  CellSet people;
  for (uint64_t key : CellsInBand(grid, T_grid_truth, reference.dynamic_points)) {
    if (!Near(truth_static, key)) people.insert(key);
  }
  GridMetrics m;
  m.occupied_cells = occupied.size();
  m.static_truth_cells = truth_static.size();
  m.people_truth_cells = people.size();
  size_t precise = 0, recalled = 0;
  for (uint64_t key : occupied) {
    if (Near(truth_static, key)) ++precise;
    if (people.count(key)) ++m.ghost_cells;
  }
  for (uint64_t key : truth_static) {
    if (Near(occupied, key)) ++recalled;
  }
  if (!occupied.empty()) m.precision = static_cast<double>(precise) / occupied.size();
  if (!truth_static.empty()) m.recall = static_cast<double>(recalled) / truth_static.size();
  return m;
}

}  // namespace

GridMetrics EvaluateGrid(const OccupancyGrid& grid, const Eigen::Isometry3d& T_truth_world,
                         const MapReference& reference) {
  CellSet occupied;
  for (int j = 0; j < grid.height; ++j) {
    for (int i = 0; i < grid.width; ++i) {
      if (grid.At(i, j) == kCellOccupied) occupied.insert(KeyOf({i, j}));
    }
  }
  const Eigen::Isometry3d T_grid_truth = (T_truth_world * grid.T_world_grid).inverse();
  return Score(occupied, grid, T_grid_truth, reference);
}

GridMetrics EvaluateOccupiedPoints(const OccupancyGrid& grid,
                                   const Eigen::Isometry3d& T_truth_world,
                                   const std::vector<Eigen::Vector3d>& points,
                                   const MapReference& reference) {
  const Eigen::Isometry3d T_grid_truth = (T_truth_world * grid.T_world_grid).inverse();
  return Score(CellsInBand(grid, T_grid_truth, points), grid, T_grid_truth, reference);
}

}  // namespace dslam
