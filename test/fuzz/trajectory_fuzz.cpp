// Fuzz harness: TUM trajectory text (dslam/io/trajectory_io.h, ParseTumTrajectory).
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "dslam/io/trajectory_io.h"
#include "fuzz_input.h"
#include "harnesses.h"

namespace dslam {
namespace fuzz {

namespace {

/// Throws ContractViolation unless `pose` has a finite stamp and translation and a rotation.
void CheckPose(const StampedPose& pose) {
  const Eigen::Matrix3d R = pose.T_world_camera.linear();
  const double orthonormal_error = (R.transpose() * R - Eigen::Matrix3d::Identity()).norm();
  if (!std::isfinite(pose.stamp_s) || !pose.T_world_camera.translation().allFinite() ||
      !(orthonormal_error < 1e-9) || !(std::abs(R.determinant() - 1.0) < 1e-9)) {
    throw ContractViolation("accepted pose '" + FormatTumLine(pose) + "'");
  }
}

}  // namespace

void TrajectoryHarness(const std::string& data) {
  ParsedOrRejected<std::runtime_error>("trajectory.txt", [&] {
    std::istringstream in(data);
    const Trajectory trajectory = ParseTumTrajectory(in, "trajectory.txt");
    for (size_t i = 0; i < trajectory.size(); ++i) {
      CheckPose(trajectory[i]);
      if (i > 0 && trajectory[i].stamp_s < trajectory[i - 1].stamp_s) {
        throw ContractViolation("poses not sorted by stamp");
      }
    }
  });
}

}  // namespace fuzz
}  // namespace dslam

DSLAM_FUZZ_TARGET(dslam::fuzz::TrajectoryHarness)
