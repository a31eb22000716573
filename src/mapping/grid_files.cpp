// map_server's pair of files for an OccupancyGrid (occupancy_grid.h).

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <stdexcept>
#include <string>

#include <yaml-cpp/yaml.h>

#include "dslam/mapping/occupancy_grid.h"

namespace dslam {
namespace {

// map_server's trinary values (its mode: trinary with negate 0 reads p = (255 - v) / 255).
constexpr unsigned char kPgmOccupied = 0;
constexpr unsigned char kPgmFree = 254;
constexpr unsigned char kPgmUnknown = 205;
constexpr int kMaxPgmSide = 100000;  // [px] a larger side is taken for a broken file

std::string ImagePath(const std::string& yaml_path) {
  const size_t slash = yaml_path.find_last_of('/');
  const size_t dot = yaml_path.find_last_of('.');
  const bool has_extension =
      dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_extension ? yaml_path.substr(0, dot) : yaml_path) + ".pgm";
}

std::string BaseName(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

void Check(const std::ofstream& out, const std::string& path) {
  if (!out) {
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  }
}

void WritePgm(const OccupancyGrid& grid, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  Check(out, path);
  out << "P5\n# dslam occupancy grid, " << grid.cell_size_m << " m per cell\n"
      << grid.width << " " << grid.height << "\n255\n";
  std::string row(static_cast<size_t>(grid.width), '\0');
  for (int j = grid.height - 1; j >= 0; --j) {  // the image's top row is the highest y
    for (int i = 0; i < grid.width; ++i) {
      const int8_t v = grid.At(i, j);
      row[static_cast<size_t>(i)] = static_cast<char>(v == kCellOccupied ? kPgmOccupied
                                                      : v == kCellFree   ? kPgmFree
                                                                         : kPgmUnknown);
    }
    out.write(row.data(), static_cast<std::streamsize>(row.size()));
  }
  out.flush();
  Check(out, path);
}

}  // namespace

void WriteMapServerFiles(const OccupancyGrid& grid, const std::string& yaml_path) {
  const std::string image_path = ImagePath(yaml_path);
  WritePgm(grid, image_path);
  std::ofstream out(yaml_path);
  Check(out, yaml_path);
  const Eigen::Quaterniond q(grid.T_world_grid.rotation());
  const Eigen::Vector3d& t = grid.T_world_grid.translation();
  out << std::setprecision(9);
  out << "# dslam occupancy grid (map_server format; map_server reads the first seven keys).\n"
      << "# The map frame G: z up, origin on the floor below the first keyframe's camera.\n"
      << "# T_world_grid: G in the world (odometry) frame, x y z qx qy qz qw [m].\n"
      << "# min/max_height_m: the obstacle band above the floor [m]; floor_from_plane: 1 when the\n"
      << "# floor is a plane of the map, 0 when grid.floor_height_m below the first camera.\n"
      << "image: " << BaseName(image_path) << "\n"
      << "resolution: " << grid.cell_size_m << "\n"
      << "origin: [" << grid.origin_m.x() << ", " << grid.origin_m.y() << ", 0.0]\n"
      << "negate: 0\n"
      << "occupied_thresh: 0.65\n"
      << "free_thresh: 0.196\n"
      << "mode: trinary\n"
      << "T_world_grid: [" << t.x() << ", " << t.y() << ", " << t.z() << ", " << q.x() << ", "
      << q.y() << ", " << q.z() << ", " << q.w() << "]\n"
      << "min_height_m: " << grid.min_height_m << "\n"
      << "max_height_m: " << grid.max_height_m << "\n"
      << "floor_from_plane: " << (grid.floor.from_plane ? 1 : 0) << "\n";
  out.flush();
  Check(out, yaml_path);
}

namespace {

// The PGM's cells (P5, 8 bits, one comment line at most between the fields).
// The PGM's size and cells (P5, 8 bits, one comment line at most between the fields).
void ReadPgm(const std::string& path, OccupancyGrid* grid) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  std::string magic;
  in >> magic;
  int width = 0, height = 0, max_value = 0;
  in >> std::ws;
  if (in.peek() == '#') in.ignore(1 << 20, '\n');
  in >> width >> height >> max_value;
  in.get();
  if (!in || magic != "P5" || width <= 0 || height <= 0 || width > kMaxPgmSide ||
      height > kMaxPgmSide || max_value != 255) {
    throw std::runtime_error(path + ": not an 8-bit binary PGM");
  }
  grid->width = width;
  grid->height = height;
  grid->cells.assign(static_cast<size_t>(width) * height, kCellUnknown);
  std::string row(static_cast<size_t>(width), '\0');
  for (int j = height - 1; j >= 0; --j) {
    if (!in.read(&row[0], width)) throw std::runtime_error(path + ": truncated");
    for (int i = 0; i < width; ++i) {
      const auto v = static_cast<unsigned char>(row[static_cast<size_t>(i)]);
      grid->cells[static_cast<size_t>(j) * width + i] = v == kPgmOccupied ? kCellOccupied
                                                        : v == kPgmFree   ? kCellFree
                                                                          : kCellUnknown;
    }
  }
}

}  // namespace

OccupancyGrid ReadMapServerFiles(const std::string& yaml_path) {
  OccupancyGrid grid;
  std::string image;
  try {
    const YAML::Node yaml = YAML::LoadFile(yaml_path);
    image = yaml["image"].as<std::string>();
    grid.cell_size_m = yaml["resolution"].as<double>();
    grid.origin_m = {yaml["origin"][0].as<double>(), yaml["origin"][1].as<double>()};
    const std::vector<double> T = yaml["T_world_grid"].as<std::vector<double>>();
    if (T.size() != 7) {
      throw std::runtime_error(yaml_path + ": not a dslam grid file: T_world_grid needs 7 numbers");
    }
    grid.T_world_grid.linear() =
        Eigen::Quaterniond(T[6], T[3], T[4], T[5]).normalized().toRotationMatrix();
    grid.T_world_grid.translation() = Eigen::Vector3d(T[0], T[1], T[2]);
    grid.min_height_m = yaml["min_height_m"].as<double>();
    grid.max_height_m = yaml["max_height_m"].as<double>();
    grid.floor.from_plane = yaml["floor_from_plane"].as<int>() != 0;
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(yaml_path + ": not a dslam grid file: " + e.what());
  }
  grid.floor.up_world = grid.T_world_grid.linear().col(2);
  grid.floor.height_m = grid.floor.up_world.dot(grid.T_world_grid.translation());
  if (!(grid.cell_size_m > 0.0)) throw std::runtime_error(yaml_path + ": resolution <= 0");
  if (image.empty()) throw std::runtime_error(yaml_path + ": no image");
  const size_t slash = yaml_path.find_last_of('/');
  const std::string image_path = image.front() == '/' || slash == std::string::npos
                                     ? image
                                     : yaml_path.substr(0, slash + 1) + image;
  ReadPgm(image_path, &grid);
  return grid;
}

}  // namespace dslam
