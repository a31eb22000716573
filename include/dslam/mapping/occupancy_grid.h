#pragma once
// A 2D occupancy grid from the static map, for planners (nav_msgs/OccupancyGrid, map_server
// files): the static map's points in a height band above the floor make their cells occupied,
// the rays of static depth (the keyframes' fused points, which leave out moving objects) make
// the cells they cross within the band free, every other cell is unknown. People never enter:
// their pixels are not fused (StaticMapper), and the rays through where they stood clear it.
//
// Frames: the grid frame G has its z axis up, its origin on the floor below the reference
// camera (the first keyframe's), its x axis the reference camera's optical axis projected onto
// the floor. Cell (i, j) covers [origin_x + i s, origin_x + (i + 1) s) x [origin_y + j s, ...)
// in G's x and y (s the cell size).

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/core/grid_config.h"

namespace dslam {

struct ViewVoteTolerance;  // dslam/mapping/view_votes.h

/// What one keyframe saw: its camera centre and its static points (the ends of its rays).
struct GridView {
  Eigen::Vector3d camera_world = Eigen::Vector3d::Zero();  ///< [m] world frame
  std::vector<Eigen::Vector3f> points_world;               ///< [m] world frame
};

/// The floor the grid stands on.
struct Floor {
  Eigen::Vector3d up_world = -Eigen::Vector3d::UnitY();  ///< unit normal of the floor, up
  double height_m = 0.0;    ///< [m] up_world . p of the floor's points, p in the world frame
  bool from_plane = false;  ///< found as a plane in the map (else grid.floor_height_m)
  int plane_points = 0;     ///< map points on that plane (0 without one)
};

/// Where `floor` came from, for messages: "a horizontal plane of the map" or
/// "grid.floor_height_m below the first camera".
const char* FloorSource(const Floor& floor);

/// Cell values, as nav_msgs/OccupancyGrid's data.
constexpr int8_t kCellUnknown = -1;
constexpr int8_t kCellFree = 0;
constexpr int8_t kCellOccupied = 100;

/// A grid and where it lies.
struct OccupancyGrid {
  double cell_size_m = 0.05;                           ///< [m] edge of a cell
  int width = 0;                                       ///< cells along G's x
  int height = 0;                                      ///< cells along G's y
  Eigen::Vector2d origin_m = Eigen::Vector2d::Zero();  ///< [m] corner of cell (0, 0) in G
  Eigen::Isometry3d T_world_grid = Eigen::Isometry3d::Identity();  ///< G in the world frame
  Floor floor;
  double min_height_m = 0.0;  ///< [m] the obstacle band above the floor (grid.min_height_m)
  double max_height_m = 0.0;  ///< [m] (grid.max_height_m)
  std::vector<int8_t> cells;  ///< row j = cells [j * width, (j + 1) * width): kCell* values

  /// The value of cell (i, j); kCellUnknown outside the grid.
  int8_t At(int i, int j) const {
    if (i < 0 || j < 0 || i >= width || j >= height) return kCellUnknown;
    return cells[static_cast<size_t>(j) * width + i];
  }
  /// The cell (i, j) holding G's point (x, y) [m] (may lie outside the grid).
  Eigen::Vector2i CellOf(const Eigen::Vector2d& xy_m) const;
  /// Counts of free and occupied cells.
  int Count(int8_t value) const;
};

/// The floor below `reference_camera_world` [m]: the plane holding the most of
/// `map_points_world` (within 3 cm; RANSAC with a fixed seed, refined by least squares) among
/// those at least 0.3 m below the camera along `up_world` (unit) whose normal lies within 30 deg
/// of `up_world`, when it holds at least 50 points and 5 % of the points below the camera; its
/// normal is then the grid's up (a camera that looks down a little does not tilt the grid).
/// Else `up_world` and config.floor_height_m below the camera.
Floor FloorOf(const std::vector<Eigen::Vector3f>& map_points_world, const Eigen::Vector3d& up_world,
              const Eigen::Vector3d& reference_camera_world, const GridConfig& config);

/// The grid of `map_points_world` (the static map, world frame) and `views` (rays), with G
/// defined by `T_world_reference` (the first keyframe's camera pose) and the floor's up
/// (FloorOf from `up_world`). A map point in the band is an obstacle when at least one view
/// measured it (within the depth noise) and the views do not see through it as often as they
/// hit it (VoteByViews with `votes`; every view votes, those before the point was fused too).
/// `cell_size_m` > 0. Occupied wins over free in a cell.
OccupancyGrid BuildOccupancyGrid(const std::vector<Eigen::Vector3f>& map_points_world,
                                 const std::vector<GridView>& views,
                                 const Eigen::Isometry3d& T_world_reference,
                                 const Eigen::Vector3d& up_world, double cell_size_m,
                                 const GridConfig& config, const ViewVoteTolerance& votes);

/// Writes `grid` as the pair ROS's map_server reads: `yaml_path` (image, resolution, origin
/// [x, y, yaw] of cell (0, 0) in G, negate 0, occupied_thresh 0.65, free_thresh 0.196, mode
/// trinary; then, for dslam's tools, T_world_grid [x y z qx qy qz qw], min_height_m, max_height_m
/// and floor_from_plane) and an 8-bit binary PGM beside it (same
/// name, extension .pgm; occupied 0, free 254, unknown 205; the first row is the highest j).
/// Throws std::runtime_error naming the file that cannot be written.
void WriteMapServerFiles(const OccupancyGrid& grid, const std::string& yaml_path);

/// Reads what WriteMapServerFiles wrote: the cells, cell size, origin, T_world_grid, the band and
/// floor_from_plane (the floor's height and up follow from T_world_grid: its origin is on the
/// floor, its z axis up). Throws std::runtime_error naming the file that is missing, unreadable
/// or not such a file.
OccupancyGrid ReadMapServerFiles(const std::string& yaml_path);

}  // namespace dslam
