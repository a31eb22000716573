#include "dslam/mapping/occupancy_grid.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>
#include <unordered_set>

#include <Eigen/Eigenvalues>

#include "dslam/mapping/view_votes.h"

namespace dslam {
namespace {

constexpr double kFloorBelowCameraM = 0.3;  // a floor lies at least this far below the camera
constexpr int kFloorMinPoints = 50;
constexpr double kFloorMinShare = 0.05;  // of the points below the camera
constexpr double kPlaneInlierM = 0.03;   // [m] a point this close to a plane lies on it
constexpr double kMaxTiltDeg = 30.0;     // the floor's normal within this of the given up
constexpr int kPlaneIterations = 300;
constexpr unsigned kPlaneSeed = 20261205u;
constexpr int kMaxCells = 4000 * 4000;  // a grid larger than this is refused (memory)
constexpr double kViewBinRad = 0.025;    // [rad] direction bins of the views' votes (about 1.4 deg)

// The rotation of G in the world frame: z = up, x = the reference camera's optical axis on the
// floor (any horizontal axis when the camera looks straight up or down).
Eigen::Matrix3d GridRotation(const Eigen::Isometry3d& T_world_reference,
                             const Eigen::Vector3d& up) {
  Eigen::Vector3d x = T_world_reference.linear().col(2);
  x -= x.dot(up) * up;
  if (x.norm() < 1e-6) {
    x = T_world_reference.linear().col(0);
    x -= x.dot(up) * up;
  }
  x.normalize();
  Eigen::Matrix3d R;
  R.col(0) = x;
  R.col(1) = up.cross(x);
  R.col(2) = up;
  return R;
}

// The 3D points in G: x, y on the floor, z the height above the floor.
struct GridFrame {
  Eigen::Isometry3d T_grid_world;
  Eigen::Vector3d ToGrid(const Eigen::Vector3d& p_world) const { return T_grid_world * p_world; }
};

// The part of segment a-b (G, z = height) with z in [z0, z1]; false when none.
bool ClipToBand(Eigen::Vector3d* a, Eigen::Vector3d* b, double z0, double z1) {
  double t0 = 0.0, t1 = 1.0;
  const double dz = b->z() - a->z();
  for (const double bound : {z0, z1}) {
    const bool lower = bound == z0;
    if (std::abs(dz) < 1e-12) {
      if (lower ? a->z() < z0 : a->z() > z1) return false;
      continue;
    }
    const double t = (bound - a->z()) / dz;
    const bool entering = lower ? dz > 0.0 : dz < 0.0;
    if (entering) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
  }
  if (t0 > t1) return false;
  const Eigen::Vector3d d = *b - *a;
  const Eigen::Vector3d start = *a + t0 * d;
  *b = *a + t1 * d;
  *a = start;
  return true;
}

// Marks free the cells of the 2D line from `from` to `to` (Bresenham), `to` itself only when
// `include_end`; occupied cells stay.
void TraceFree(const Eigen::Vector2i& from, const Eigen::Vector2i& to, bool include_end,
               OccupancyGrid* grid) {
  int x = from.x(), y = from.y();
  const int dx = std::abs(to.x() - x), dy = -std::abs(to.y() - y);
  const int sx = x < to.x() ? 1 : -1, sy = y < to.y() ? 1 : -1;
  int error = dx + dy;
  for (;;) {
    const bool end = x == to.x() && y == to.y();
    if (end && !include_end) return;
    if (x >= 0 && y >= 0 && x < grid->width && y < grid->height) {
      int8_t& cell = grid->cells[static_cast<size_t>(y) * grid->width + x];
      if (cell != kCellOccupied) cell = kCellFree;
    }
    if (end) return;
    const int e2 = 2 * error;
    if (e2 >= dy) {
      error += dy;
      x += sx;
    }
    if (e2 <= dx) {
      error += dx;
      y += sy;
    }
  }
}

// A plane n . p = offset (n unit) and the points within kPlaneInlierM of it.
struct Plane {
  Eigen::Vector3d normal;
  double offset = 0.0;
  int inliers = 0;
};

int CountInliers(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& normal,
                 double offset, Eigen::Vector3d* sum, Eigen::Matrix3d* outer) {
  int count = 0;
  for (const Eigen::Vector3d& p : points) {
    if (std::abs(normal.dot(p) - offset) > kPlaneInlierM) continue;
    ++count;
    if (sum != nullptr) {
      *sum += p;
      *outer += p * p.transpose();
    }
  }
  return count;
}

// The plane with the most of `points` among those whose normal is within kMaxTiltDeg of `up`
// (RANSAC over a fixed-seed sample, then the least-squares plane of its inliers).
std::optional<Plane> LargestPlane(const std::vector<Eigen::Vector3d>& points,
                                  const Eigen::Vector3d& up) {
  if (points.size() < 3) return std::nullopt;
  std::mt19937 rng(kPlaneSeed);
  std::uniform_int_distribution<size_t> pick(0, points.size() - 1);
  const double min_cos = std::cos(kMaxTiltDeg * M_PI / 180.0);
  std::optional<Plane> best;
  for (int iteration = 0; iteration < kPlaneIterations; ++iteration) {
    const Eigen::Vector3d& a = points[pick(rng)];
    Eigen::Vector3d n = (points[pick(rng)] - a).cross(points[pick(rng)] - a);
    if (n.norm() < 1e-9) continue;
    n.normalize();
    if (n.dot(up) < 0.0) n = -n;
    if (n.dot(up) < min_cos) continue;
    const int inliers = CountInliers(points, n, n.dot(a), nullptr, nullptr);
    if (!best || inliers > best->inliers) best = Plane{n, n.dot(a), inliers};
  }
  if (!best) return std::nullopt;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  const int count = CountInliers(points, best->normal, best->offset, &sum, &outer);
  const Eigen::Vector3d mean = sum / count;
  const Eigen::Matrix3d covariance = outer / count - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  Eigen::Vector3d n = eigen.eigenvectors().col(0);  // the smallest eigenvalue's
  if (n.dot(up) < 0.0) n = -n;
  if (n.dot(up) >= min_cos) {
    best->normal = n;
    best->offset = n.dot(mean);
    best->inliers = CountInliers(points, n, best->offset, nullptr, nullptr);
  }
  return best;
}

}  // namespace

const char* FloorSource(const Floor& floor) {
  return floor.from_plane ? "a horizontal plane of the map"
                          : "grid.floor_height_m below the first camera";
}

Eigen::Vector2i OccupancyGrid::CellOf(const Eigen::Vector2d& xy_m) const {
  const Eigen::Vector2d c = (xy_m - origin_m) / cell_size_m;
  return {static_cast<int>(std::floor(c.x())), static_cast<int>(std::floor(c.y()))};
}

int OccupancyGrid::Count(int8_t value) const {
  return static_cast<int>(std::count(cells.begin(), cells.end(), value));
}

Floor FloorOf(const std::vector<Eigen::Vector3f>& map_points_world, const Eigen::Vector3d& up_world,
              const Eigen::Vector3d& reference_camera_world, const GridConfig& config) {
  Floor floor;
  floor.up_world = up_world;
  const double camera_height = up_world.dot(reference_camera_world);
  floor.height_m = camera_height - config.floor_height_m;
  std::vector<Eigen::Vector3d> below;
  for (const Eigen::Vector3f& p : map_points_world) {
    const Eigen::Vector3d q = p.cast<double>();
    if (up_world.dot(q) <= camera_height - kFloorBelowCameraM) below.push_back(q);
  }
  const std::optional<Plane> plane = LargestPlane(below, up_world);
  if (!plane || plane->inliers < kFloorMinPoints ||
      plane->inliers < kFloorMinShare * static_cast<double>(below.size())) {
    return floor;
  }
  floor.up_world = plane->normal;
  floor.height_m = plane->offset;
  floor.from_plane = true;
  floor.plane_points = plane->inliers;
  return floor;
}

namespace {

// The grid's extent: `obstacles` (G), the cameras and the ends of their rays, with a cell of
// margin. Throws when it exceeds kMaxCells.
void SizeGrid(const std::vector<Eigen::Vector3d>& obstacles, const std::vector<GridView>& views,
              const GridFrame& frame, OccupancyGrid* grid) {
  Eigen::AlignedBox2d box;
  for (const Eigen::Vector3d& g : obstacles) box.extend(g.head<2>());
  for (const GridView& view : views) {
    box.extend(frame.ToGrid(view.camera_world).head<2>());
    for (const Eigen::Vector3f& p : view.points_world) {
      box.extend(frame.ToGrid(p.cast<double>()).head<2>());
    }
  }
  if (box.isEmpty()) box.extend(Eigen::Vector2d::Zero());
  const double s = grid->cell_size_m;
  grid->origin_m = (box.min() / s).array().floor() * s - s;
  const Eigen::Vector2d size = box.max() - grid->origin_m;
  grid->width = static_cast<int>(std::ceil(size.x() / s)) + 1;
  grid->height = static_cast<int>(std::ceil(size.y() / s)) + 1;
  if (static_cast<double>(grid->width) * grid->height > kMaxCells) {
    throw std::runtime_error("BuildOccupancyGrid: " + std::to_string(grid->width) + " x " +
                             std::to_string(grid->height) + " cells exceed the limit " +
                             std::to_string(kMaxCells) + " (grid.cell_size_m too small?)");
  }
}

// The points of `map_points_world` in the grid's band that a view measured and that the views
// do not see through (FreeSpaceTolerance::Transient of their votes, VoteByViews), in G: a moving
// object's point that entered the map stays out of the grid when views, before or after, saw
// past it as often as they hit it; a point no view measured within the depth noise (a depth
// outlier behind a wall, whose own view's nearest range in that direction is the wall's) too.
std::vector<Eigen::Vector3d> Obstacles(const std::vector<Eigen::Vector3f>& map_points_world,
                                       const std::vector<GridView>& views, const GridFrame& frame,
                                       const OccupancyGrid& grid,
                                       const ViewVoteTolerance& tolerance) {
  std::vector<Eigen::Vector3f> in_band;
  std::vector<Eigen::Vector3d> in_band_grid;
  for (const Eigen::Vector3f& p : map_points_world) {
    const Eigen::Vector3d g = frame.ToGrid(p.cast<double>());
    if (!(g.z() >= grid.min_height_m && g.z() <= grid.max_height_m)) continue;
    in_band.push_back(p);
    in_band_grid.push_back(g);
  }
  const std::vector<RayVotes> votes = VoteByViews(in_band, views, tolerance, kViewBinRad);
  std::vector<Eigen::Vector3d> kept;
  for (size_t k = 0; k < in_band.size(); ++k) {
    const RayVotes& v = votes[k];
    if (v.measured >= 1 && !tolerance.see_through.Transient(v.misses, v.hits)) {
      kept.push_back(in_band_grid[k]);
    }
  }
  return kept;
}

// Marks free the cells `view`'s rays cross within the band (a floor point's cell too, not the
// cell of a point in the band: what the ray hit), one trace per distinct pair of cells.
void ClearAlongRays(const GridView& view, const GridFrame& frame, OccupancyGrid* grid) {
  const double z0 = grid->min_height_m, z1 = grid->max_height_m;
  const Eigen::Vector3d camera = frame.ToGrid(view.camera_world);
  std::unordered_set<uint64_t> traced;  // (start cell, end cell, end included)
  for (const Eigen::Vector3f& p : view.points_world) {
    const Eigen::Vector3d end = frame.ToGrid(p.cast<double>());
    Eigen::Vector3d a = camera, b = end;
    const bool ends_below = end.z() < z0;  // the floor seen there: its cell is free too
    const bool ends_in_band = end.z() <= z1 && !ends_below;
    if (!ClipToBand(&a, &b, z0, z1)) {
      if (!ends_below) continue;
      a = end;  // a ray below the band all along: only the floor point's cell
    }
    const Eigen::Vector2i from = grid->CellOf(a.head<2>());
    const Eigen::Vector2d to_xy =
        ends_below ? Eigen::Vector2d(end.head<2>()) : Eigen::Vector2d(b.head<2>());
    const Eigen::Vector2i to = grid->CellOf(to_xy);
    const uint64_t key = (static_cast<uint64_t>(from.x() & 0x7fff) << 49) |
                         (static_cast<uint64_t>(from.y() & 0x7fff) << 34) |
                         (static_cast<uint64_t>(to.x() & 0x7fff) << 19) |
                         (static_cast<uint64_t>(to.y() & 0x7fff) << 4) | (ends_in_band ? 1 : 0);
    if (!traced.insert(key).second) continue;
    TraceFree(from, to, !ends_in_band, grid);
  }
}

}  // namespace

OccupancyGrid BuildOccupancyGrid(const std::vector<Eigen::Vector3f>& map_points_world,
                                 const std::vector<GridView>& views,
                                 const Eigen::Isometry3d& T_world_reference,
                                 const Eigen::Vector3d& up_world, double cell_size_m,
                                 const GridConfig& config, const ViewVoteTolerance& votes) {
  if (!(cell_size_m > 0.0)) throw std::invalid_argument("BuildOccupancyGrid: cell size <= 0");
  OccupancyGrid grid;
  grid.cell_size_m = cell_size_m;
  grid.min_height_m = config.min_height_m;
  grid.max_height_m = config.max_height_m;
  grid.floor =
      FloorOf(map_points_world, up_world.normalized(), T_world_reference.translation(), config);
  // G: origin on the floor below the reference camera.
  const Eigen::Vector3d& up = grid.floor.up_world;
  const Eigen::Vector3d c = T_world_reference.translation();
  grid.T_world_grid.linear() = GridRotation(T_world_reference, up);
  grid.T_world_grid.translation() = c - (up.dot(c) - grid.floor.height_m) * up;
  const GridFrame frame{grid.T_world_grid.inverse()};
  const std::vector<Eigen::Vector3d> obstacles =
      Obstacles(map_points_world, views, frame, grid, votes);
  SizeGrid(obstacles, views, frame, &grid);
  grid.cells.assign(static_cast<size_t>(grid.width) * grid.height, kCellUnknown);
  for (const Eigen::Vector3d& g : obstacles) {
    const Eigen::Vector2i cell = grid.CellOf(g.head<2>());
    grid.cells[static_cast<size_t>(cell.y()) * grid.width + cell.x()] = kCellOccupied;
  }
  for (const GridView& view : views) ClearAlongRays(view, frame, &grid);
  return grid;
}

}  // namespace dslam
