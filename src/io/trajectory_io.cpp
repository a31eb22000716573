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

bool ReadDataLine(std::istream& in, std::string* line, int* line_number) {
  while (std::getline(in, *line)) {
    ++*line_number;
    const size_t first = line->find_first_not_of(" \t\r");
    if (first != std::string::npos && (*line)[first] != '#') return true;
  }
  return false;
}

Eigen::Isometry3d PoseFromTumFields(const double fields[7], const std::string& where) {
  Eigen::Quaterniond q(fields[6], fields[3], fields[4], fields[5]);
  // stableNorm: norm() overflows to infinity for coefficients beyond ~1e154, and the
  // quaternion then normalised to zero (read as the identity rotation).
  const double norm = q.coeffs().stableNorm();
  if (!(norm > 1e-6)) throw std::runtime_error(where + "zero quaternion");
  q.coeffs() /= norm;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = q.toRotationMatrix();
  pose.translation() = Eigen::Vector3d(fields[0], fields[1], fields[2]);
  return pose;
}

Trajectory ParseTumTrajectory(std::istream& in, const std::string& path) {
  Trajectory trajectory;
  std::string line;
  int line_number = 0;
  while (ReadDataLine(in, &line, &line_number)) {
    const std::string where = path + ":" + std::to_string(line_number) + ": ";
    std::istringstream fields(line);
    StampedPose pose;
    double f[7];
    if (!(fields >> pose.stamp_s >> f[0] >> f[1] >> f[2] >> f[3] >> f[4] >> f[5] >> f[6])) {
      throw std::runtime_error(where + "expected 'timestamp tx ty tz qx qy qz qw'");
    }
    pose.T_world_camera = PoseFromTumFields(f, where);
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
