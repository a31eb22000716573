// The occupancy grid with known answers: a floor found under a tilted camera, a wall and a box
// occupied, the floor between the camera and the wall free, behind the wall unknown, a person's
// place cleared by rays that pass where it stood, and map_server's files read back.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <octomap/OcTree.h>
#include <yaml-cpp/yaml.h>

#include "dslam/core/config.h"
#include "dslam/mapping/occupancy_grid.h"
#include "dslam/mapping/octomap_file.h"
#include "dslam/mapping/view_votes.h"

namespace dslam {
namespace {

// A room in a world whose up is +z (the tests pass up (0, 0, 1) or a tilted one): the floor z = 0
// over x in [0, 4], y in [-2, 2]; a wall x = 4.025 (a cell centre) from z 0.05 to 2.5 (its points
// more than the plane tolerance of 3 cm above the floor); a box 0.4 m high at x in [2, 2.4], y in
// [-0.2, 0.2]. Points every 2 cm.
std::vector<Eigen::Vector3f> Room() {
  std::vector<Eigen::Vector3f> points;
  for (double x = 0.01; x < 4.0; x += 0.02) {
    for (double y = -1.99; y < 2.0; y += 0.02) points.emplace_back(x, y, 0.0);
  }
  for (double y = -1.99; y < 2.0; y += 0.02) {
    for (double z = 0.05; z < 2.5; z += 0.02) points.emplace_back(4.025, y, z);
  }
  for (double x = 2.01; x < 2.4; x += 0.02) {
    for (double y = -0.19; y < 0.2; y += 0.02) points.emplace_back(x, y, 0.4);
  }
  return points;
}

// A camera at (0, 0, 1.3) looking along +x (optical z = +x, optical y = -z: up is -y).
Eigen::Isometry3d Camera() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  Eigen::Matrix3d R;
  R.col(0) = Eigen::Vector3d(0, -1, 0);
  R.col(1) = Eigen::Vector3d(0, 0, -1);
  R.col(2) = Eigen::Vector3d(1, 0, 0);
  T.linear() = R;
  T.translation() = Eigen::Vector3d(0, 0, 1.3);
  return T;
}

GridView ViewOf(const Eigen::Isometry3d& T_world_camera,
                const std::vector<Eigen::Vector3f>& points) {
  GridView view;
  view.camera_world = T_world_camera.translation();
  view.points_world = points;
  return view;
}

GridConfig Defaults() { return Config().grid; }

// The default vote tolerances (misses: 5 cm + 2 % of the range; hits: 2.5 cm + 2 sigma_d).
ViewVoteTolerance SeeThrough() { return ViewVoteTolerance::From(Config()); }

// The value of the cell holding the world point (x, y) of a grid whose G is the world's x, y.
int8_t CellAt(const OccupancyGrid& grid, double x, double y) {
  const Eigen::Vector3d g = grid.T_world_grid.inverse() * Eigen::Vector3d(x, y, 0.0);
  const Eigen::Vector2i c = grid.CellOf(g.head<2>());
  return grid.At(c.x(), c.y());
}

TEST(Floor, PlaneFoundUnderATiltedUpAndItsNormalTaken) {
  const std::vector<Eigen::Vector3f> room = Room();
  // The given up leans 8 deg off the floor's normal (a camera looking down a little).
  const Eigen::Vector3d up =
      Eigen::AngleAxisd(8.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()) * Eigen::Vector3d::UnitZ();
  const Floor floor = FloorOf(room, up, Eigen::Vector3d(0, 0, 1.3), Defaults());
  ASSERT_TRUE(floor.from_plane);
  EXPECT_NEAR(floor.up_world.z(), 1.0, 1e-6);
  EXPECT_NEAR(floor.height_m, 0.0, 1e-6);
  EXPECT_EQ(floor.plane_points, 200 * 200);
}

TEST(Floor, WithoutAPlaneTheConfiguredHeightBelowTheCamera) {
  std::vector<Eigen::Vector3f> wall;  // only the wall: nothing horizontal below the camera
  for (double y = -1.99; y < 2.0; y += 0.02) {
    for (double z = 0.01; z < 2.5; z += 0.02) wall.emplace_back(4.0, y, z);
  }
  GridConfig config = Defaults();
  config.floor_height_m = 1.1;
  const Floor floor = FloorOf(wall, Eigen::Vector3d::UnitZ(), Eigen::Vector3d(0, 0, 1.3), config);
  EXPECT_FALSE(floor.from_plane);
  EXPECT_NEAR(floor.height_m, 0.2, 1e-12);
  EXPECT_EQ(floor.up_world, Eigen::Vector3d::UnitZ());
}

TEST(OccupancyGrid, WallAndBoxOccupiedFloorFreeBehindUnknown) {
  const std::vector<Eigen::Vector3f> room = Room();
  const Eigen::Isometry3d camera = Camera();
  std::vector<Eigen::Vector3f> seen;  // what the camera sees: the room in front of the wall
  for (const Eigen::Vector3f& p : room) {
    if (std::abs(p.y()) < 1.5) seen.push_back(p);
  }
  const OccupancyGrid grid = BuildOccupancyGrid(room, {ViewOf(camera, seen)}, camera,
                                                -camera.linear().col(1), 0.05, Defaults(), SeeThrough());
  ASSERT_TRUE(grid.floor.from_plane);
  EXPECT_EQ(CellAt(grid, 4.025, 0.0), kCellOccupied);  // the wall
  EXPECT_EQ(CellAt(grid, 2.2, 0.0), kCellOccupied);    // the box
  EXPECT_EQ(CellAt(grid, 1.0, 0.0), kCellFree);        // floor between camera and box
  EXPECT_EQ(CellAt(grid, 3.0, 1.0), kCellFree);        // floor beside the box
  EXPECT_EQ(CellAt(grid, 3.0, 1.9), kCellUnknown);     // never seen (|y| >= 1.5 left out)
  EXPECT_EQ(CellAt(grid, 5.0, 0.0), kCellUnknown);     // outside the grid, behind the wall
  // The floor itself is never an obstacle: only the wall's and the box's cells are occupied.
  const int wall_cells = 4 / 0.05 + 1, box_cells = 8 * 8;
  EXPECT_LE(grid.Count(kCellOccupied), 2 * wall_cells + box_cells + 2 * (8 + 8));
}

TEST(OccupancyGrid, RaysThroughWhereAPersonStoodLeaveNoObstacle) {
  // The map holds no person (its pixels are never fused); the rays of a later keyframe pass
  // where the person stood, so those cells are free, not unknown or occupied.
  const std::vector<Eigen::Vector3f> room = Room();
  const Eigen::Isometry3d camera = Camera();
  const OccupancyGrid grid = BuildOccupancyGrid(room, {ViewOf(camera, room)}, camera,
                                                -camera.linear().col(1), 0.05, Defaults(), SeeThrough());
  EXPECT_EQ(CellAt(grid, 1.5, -0.5), kCellFree);
  EXPECT_EQ(CellAt(grid, 3.0, 0.6), kCellFree);
}

TEST(OccupancyGrid, APersonsPointsInTheMapThatAnotherViewSawThroughLeaveNoObstacle) {
  // A person (a column 0.3 m wide at x 1.5, y -0.5, 0.2-1.7 m high) entered the map from the
  // view that measured it; a view from the same place before the person came saw the wall through
  // it. The person's cells are no obstacle; the box, which both measured, stays one.
  const std::vector<Eigen::Vector3f> room = Room();
  const Eigen::Isometry3d camera = Camera();
  std::vector<Eigen::Vector3f> person;
  for (double y = -0.65; y < -0.35; y += 0.02) {
    for (double z = 0.2; z < 1.7; z += 0.02) person.emplace_back(1.5, y, z);
  }
  std::vector<Eigen::Vector3f> map = room, with_person = room;
  map.insert(map.end(), person.begin(), person.end());
  with_person.insert(with_person.end(), person.begin(), person.end());
  const OccupancyGrid only_its_view =
      BuildOccupancyGrid(map, {ViewOf(camera, with_person)}, camera, -camera.linear().col(1), 0.05,
                         Defaults(), SeeThrough());
  EXPECT_EQ(CellAt(only_its_view, 1.5, -0.5), kCellOccupied);  // nothing saw through it
  const OccupancyGrid grid = BuildOccupancyGrid(
      map, {ViewOf(camera, room), ViewOf(camera, with_person)}, camera, -camera.linear().col(1),
      0.05, Defaults(), SeeThrough());
  for (double y = -0.6; y < -0.35; y += 0.05) EXPECT_EQ(CellAt(grid, 1.5, y), kCellFree) << y;
  EXPECT_EQ(CellAt(grid, 2.2, 0.0), kCellOccupied);  // the box
  EXPECT_EQ(CellAt(grid, 4.025, 0.0), kCellOccupied);  // the wall
}

TEST(OccupancyGrid, MapServerFilesReadBack) {
  const std::vector<Eigen::Vector3f> room = Room();
  const Eigen::Isometry3d camera = Camera();
  const OccupancyGrid grid = BuildOccupancyGrid(room, {ViewOf(camera, room)}, camera,
                                                -camera.linear().col(1), 0.1, Defaults(), SeeThrough());
  const std::string yaml_path = ::testing::TempDir() + "/dslam_grid_test.yaml";
  WriteMapServerFiles(grid, yaml_path);
  const YAML::Node yaml = YAML::LoadFile(yaml_path);
  EXPECT_EQ(yaml["image"].as<std::string>(), "dslam_grid_test.pgm");
  EXPECT_DOUBLE_EQ(yaml["resolution"].as<double>(), 0.1);
  EXPECT_NEAR(yaml["origin"][0].as<double>(), grid.origin_m.x(), 1e-9);
  EXPECT_NEAR(yaml["origin"][1].as<double>(), grid.origin_m.y(), 1e-9);
  EXPECT_EQ(yaml["origin"][2].as<double>(), 0.0);
  EXPECT_EQ(yaml["negate"].as<int>(), 0);
  EXPECT_DOUBLE_EQ(yaml["occupied_thresh"].as<double>(), 0.65);
  EXPECT_DOUBLE_EQ(yaml["free_thresh"].as<double>(), 0.196);
  EXPECT_EQ(yaml["mode"].as<std::string>(), "trinary");
  const std::vector<double> T = yaml["T_world_grid"].as<std::vector<double>>();
  ASSERT_EQ(T.size(), 7u);
  const Eigen::Quaterniond q(T[6], T[3], T[4], T[5]);
  EXPECT_TRUE(q.toRotationMatrix().isApprox(grid.T_world_grid.rotation(), 1e-6));
  EXPECT_TRUE(Eigen::Vector3d(T[0], T[1], T[2]).isApprox(grid.T_world_grid.translation(), 1e-6));
  EXPECT_DOUBLE_EQ(yaml["min_height_m"].as<double>(), Defaults().min_height_m);
  EXPECT_DOUBLE_EQ(yaml["max_height_m"].as<double>(), Defaults().max_height_m);
  EXPECT_EQ(yaml["floor_from_plane"].as<int>(), 1);

  std::ifstream pgm(::testing::TempDir() + "/dslam_grid_test.pgm", std::ios::binary);
  std::string magic, comment;
  int width = 0, height = 0, max_value = 0;
  pgm >> magic;
  pgm.get();
  std::getline(pgm, comment);
  pgm >> width >> height >> max_value;
  pgm.get();
  ASSERT_EQ(magic, "P5");
  ASSERT_EQ(width, grid.width);
  ASSERT_EQ(height, grid.height);
  ASSERT_EQ(max_value, 255);
  std::vector<unsigned char> pixels(static_cast<size_t>(width) * height);
  pgm.read(reinterpret_cast<char*>(pixels.data()), static_cast<std::streamsize>(pixels.size()));
  ASSERT_TRUE(pgm);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const unsigned char v = pixels[static_cast<size_t>(height - 1 - j) * width + i];
      const int8_t cell = grid.At(i, j);
      ASSERT_EQ(v, cell == kCellOccupied ? 0 : cell == kCellFree ? 254 : 205) << i << " " << j;
    }
  }
  const OccupancyGrid read = ReadMapServerFiles(yaml_path);
  EXPECT_EQ(read.cells, grid.cells);
  EXPECT_EQ(read.width, grid.width);
  EXPECT_EQ(read.height, grid.height);
  EXPECT_TRUE(read.origin_m.isApprox(grid.origin_m, 1e-9));
  EXPECT_TRUE(read.T_world_grid.isApprox(grid.T_world_grid, 1e-6));
  EXPECT_NEAR(read.floor.height_m, grid.floor.height_m, 1e-6);
  EXPECT_EQ(read.floor.from_plane, grid.floor.from_plane);
  std::remove(yaml_path.c_str());
}

TEST(OccupancyGrid, ReadingAFileThatIsNoGridNamesIt) {
  const std::string path = ::testing::TempDir() + "/dslam_not_a_grid.yaml";
  std::ofstream(path) << "image: x.pgm\nresolution: 0.05\n";
  try {
    ReadMapServerFiles(path);
    FAIL() << "a file without origin was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

TEST(OctoMapFile, HitsAtTheSurfacesMissesAlongTheRaysReadBackWithLiboctomap) {
  // The room seen by the camera (rays to its points) and the map's points: the wall and the box
  // occupied, the air between camera and wall free, behind the wall unknown.
  const std::vector<Eigen::Vector3f> room = Room();
  StaticMapRays rays;
  rays.points_world = room;
  rays.views = {ViewOf(Camera(), room)};
  const std::string path = ::testing::TempDir() + "/dslam_octomap_test.bt";
  const OctoMapStats stats = WriteOctoMap(rays, 0.05, path);
  EXPECT_GT(stats.occupied_leaves, 0u);
  EXPECT_GT(stats.free_leaves, 0u);
  octomap::OcTree tree(0.1);
  ASSERT_TRUE(tree.readBinary(path));
  EXPECT_DOUBLE_EQ(tree.getResolution(), 0.05);
  const auto occupied = [&](double x, double y, double z) {
    const octomap::OcTreeNode* node = tree.search(x, y, z);
    return node == nullptr ? -1 : tree.isNodeOccupied(node) ? 1 : 0;
  };
  EXPECT_EQ(occupied(4.025, 0.0, 1.0), 1);  // the wall
  EXPECT_EQ(occupied(2.2, 0.0, 0.4), 1);    // the box's top
  EXPECT_EQ(occupied(2.0, 0.0, 1.3), 0);    // the air at the camera's height
  EXPECT_EQ(occupied(1.0, 1.0, 0.6), 0);    // above the floor, beside the ray to the box
  EXPECT_EQ(occupied(5.0, 0.0, 1.0), -1);   // behind the wall: never seen
  std::remove(path.c_str());
}

TEST(GridConfig, BandAndUpValidated) {
  Config config;
  config.grid.min_height_m = 2.0;
  config.grid.max_height_m = 1.0;
  EXPECT_THROW(config.Validate(), ConfigError);
  config = Config();
  config.grid.up_x = config.grid.up_y = config.grid.up_z = 0.0;
  try {
    config.Validate();
    FAIL() << "a zero up vector was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("grid.up_x"), std::string::npos);
  }
}

}  // namespace
}  // namespace dslam
