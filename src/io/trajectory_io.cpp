#include "dslam/io/trajectory_io.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace dslam {

const char kTumTrajectoryHeader[] =
    "# timestamp tx ty tz qx qy qz qw (T_world_camera, camera optical frame)\n";

Trajectory ReadTumTrajectory(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open trajectory " + path);
  return ParseTumTrajectory(in, path);
}

Trajectory ParseTumTrajectory(std::istream& in, const std::string& path) {
  Trajectory trajectory;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream fields(line);
    double t, x, y, z, qx, qy, qz, qw;
    if (!(fields >> t >> x >> y >> z >> qx >> qy >> qz >> qw)) {
      throw std::runtime_error(path + ":" + std::to_string(line_number) +
                               ": expected 'timestamp tx ty tz qx qy qz qw'");
    }
    Eigen::Quaterniond q(qw, qx, qy, qz);
    // stableNorm: norm() overflows to infinity for coefficients beyond ~1e154, and the
    // quaternion then normalised to zero (read as the identity rotation).
    const double norm = q.coeffs().stableNorm();
    if (!(norm > 1e-6)) {
      throw std::runtime_error(path + ":" + std::to_string(line_number) + ": zero quaternion");
    }
    StampedPose pose;
    pose.stamp_s = t;
    q.coeffs() /= norm;
    pose.T_world_camera.linear() = q.toRotationMatrix();
    pose.T_world_camera.translation() = Eigen::Vector3d(x, y, z);
    trajectory.push_back(pose);
  }
  std::stable_sort(
      trajectory.begin(), trajectory.end(),
      [](const StampedPose& a, const StampedPose& b) { return a.stamp_s < b.stamp_s; });
  return trajectory;
}

std::string FormatTumLine(const StampedPose& pose) {
  const Eigen::Vector3d& p = pose.T_world_camera.translation();
  const Eigen::Quaterniond q(pose.T_world_camera.rotation());
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), "%.6f %.6f %.6f %.6f %.7f %.7f %.7f %.7f", pose.stamp_s,
                p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w());
  return buffer;
}

void WriteTumTrajectory(const std::string& path, const Trajectory& trajectory) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write trajectory " + path);
  out << kTumTrajectoryHeader;
  for (const StampedPose& pose : trajectory) out << FormatTumLine(pose) << "\n";
  if (!out) throw std::runtime_error("error while writing trajectory " + path);
}

}  // namespace dslam
