// Reading moving-object files (object_files.h).
#include "dslam/eval/object_files.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace dslam {
namespace {

/// Calls `add` with the `count` numbers of every non-comment line of `in`.
template <typename Add>
void ParseNumberLines(std::istream& in, const std::string& name, int count, const char* columns,
                      Add add) {
  std::string line;
  int line_number = 0;
  std::vector<double> values(count);
  while (std::getline(in, line)) {
    ++line_number;
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream fields(line);
    for (int k = 0; k < count; ++k) {
      if (!(fields >> values[k]) || !std::isfinite(values[k])) {
        throw std::runtime_error(name + ":" + std::to_string(line_number) + ": expected '" +
                                 columns + "' (finite numbers)");
      }
    }
    add(values);
  }
}

/// The id column: a whole number in [0, 2^31), else std::runtime_error.
int IdOf(double value, const std::string& name) {
  if (!(value >= 0.0 && value < 2147483648.0) || value != std::floor(value)) {
    throw std::runtime_error(name + ": object id " + std::to_string(value) +
                             " is not a whole number in [0, 2^31)");
  }
  return static_cast<int>(value);
}

std::ifstream Open(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  return in;
}

}  // namespace

std::vector<TruthObject> ParseTruthObjects(std::istream& in, const std::string& name) {
  std::vector<TruthObject> objects;
  ParseNumberLines(in, name, 9, "timestamp id x y z vx vy vz pixel_share",
                   [&](const std::vector<double>& v) {
                     TruthObject o;
                     o.stamp_s = v[0];
                     o.id = IdOf(v[1], name);
                     o.position_m = Eigen::Vector3d(v[2], v[3], v[4]);
                     o.velocity_mps = Eigen::Vector3d(v[5], v[6], v[7]);
                     o.pixel_share = v[8];
                     objects.push_back(o);
                   });
  return objects;
}

std::vector<TruthObject> ReadTruthObjects(const std::string& path) {
  std::ifstream in = Open(path);
  return ParseTruthObjects(in, path);
}

std::vector<EstimatedObject> ParseEstimatedObjects(std::istream& in, const std::string& name) {
  std::vector<EstimatedObject> objects;
  ParseNumberLines(in, name, 11, "timestamp id x y z vx vy vz ex ey ez",
                   [&](const std::vector<double>& v) {
                     EstimatedObject o;
                     o.stamp_s = v[0];
                     o.id = IdOf(v[1], name);
                     o.position_m = Eigen::Vector3d(v[2], v[3], v[4]);
                     o.velocity_mps = Eigen::Vector3d(v[5], v[6], v[7]);
                     o.extent_m = Eigen::Vector3d(v[8], v[9], v[10]);
                     objects.push_back(o);
                   });
  return objects;
}

std::vector<EstimatedObject> ReadEstimatedObjects(const std::string& path) {
  std::ifstream in = Open(path);
  return ParseEstimatedObjects(in, path);
}

}  // namespace dslam
