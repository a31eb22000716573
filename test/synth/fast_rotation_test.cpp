// Tests of the fast_rotation scenario's camera motion (after TUM fr1/rpy): angular-rate peaks,
// position bound, start pose, and that no other scenario has blur or hand shake.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dslam/synth/scenario.h"

namespace dslam {
namespace synth {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

/// Statistics of a camera motion sampled every `dt_s` over [0, duration_s].
struct MotionStats {
  Eigen::Vector3d peak_body_rate_dps = Eigen::Vector3d::Zero();  ///< |w| per camera axis x, y, z
  double peak_speed_dps = 0.0;                                   ///< [deg/s] max |w|
  double mean_speed_dps = 0.0;                                   ///< [deg/s] mean |w|
  double max_distance_m = 0.0;  ///< [m] largest distance of the camera centre from its start
};

/// Body angular velocity (camera frame) from R(t)^T R(t + dt), by finite differences.
MotionStats SampleMotion(const CameraMotionParams& motion, double duration_s, double dt_s) {
  MotionStats stats;
  const Eigen::Isometry3d T_world_camera_start = CameraPoseAt(motion, 0.0, 1);
  int samples = 0;
  for (double t = 0.0; t < duration_s; t += dt_s, ++samples) {
    const Eigen::Isometry3d a = CameraPoseAt(motion, t, 1), b = CameraPoseAt(motion, t + dt_s, 1);
    const Eigen::AngleAxisd delta(a.linear().transpose() * b.linear());
    const Eigen::Vector3d w_dps = delta.axis() * delta.angle() / dt_s * kRadToDeg;
    stats.peak_body_rate_dps = stats.peak_body_rate_dps.cwiseMax(w_dps.cwiseAbs());
    stats.peak_speed_dps = std::max(stats.peak_speed_dps, w_dps.norm());
    stats.mean_speed_dps += w_dps.norm();
    stats.max_distance_m = std::max(stats.max_distance_m,
                                    (a.translation() - T_world_camera_start.translation()).norm());
  }
  stats.mean_speed_dps /= samples;
  return stats;
}

TEST(SynthFastRotation, ScenarioParameters) {
  const Scenario s = MakeScenario("fast_rotation", 2);
  EXPECT_EQ(s.frames, 720);
  EXPECT_EQ(s.fps, 30.0);
  EXPECT_EQ(s.camera.kind, CameraMotionKind::kRpy);
  EXPECT_EQ(s.camera.exposure.exposure_s, 0.015);
  EXPECT_TRUE(s.walkers.empty() && s.boxes.empty() && s.sheets.empty());
  for (int axis = 0; axis < 3; ++axis) {  // periods 2-4 s, different per axis
    EXPECT_GE(s.camera.rpy_period_s[axis], 2.0);
    EXPECT_LE(s.camera.rpy_period_s[axis], 4.0);
    EXPECT_NE(s.camera.rpy_period_s[axis], s.camera.rpy_period_s[(axis + 1) % 3]);
  }
}

TEST(SynthFastRotation, AngularRatePeaksAndPositionBound) {
  const Scenario s = MakeScenario("fast_rotation", 1);
  const MotionStats m = SampleMotion(s.camera, s.frames / s.fps, 1e-3);
  std::printf(
      "fast_rotation over %d frames: peak body rates x (pitch) %.2f, y (yaw) %.2f, z "
      "(roll) %.2f deg/s; |w| peak %.2f mean %.2f deg/s; max distance %.4f m\n",
      s.frames, m.peak_body_rate_dps.x(), m.peak_body_rate_dps.y(), m.peak_body_rate_dps.z(),
      m.peak_speed_dps, m.mean_speed_dps, m.max_distance_m);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_GE(m.peak_body_rate_dps[axis], 50.0) << "axis " << axis;
    EXPECT_LE(m.peak_body_rate_dps[axis], 60.0) << "axis " << axis;
  }
  // Known answers of this motion (sampled at 1 ms over 24 s).
  EXPECT_NEAR(m.peak_body_rate_dps.x(), 55.1, 0.2);
  EXPECT_NEAR(m.peak_body_rate_dps.y(), 52.9, 0.2);
  EXPECT_NEAR(m.peak_body_rate_dps.z(), 53.0, 0.2);
  EXPECT_NEAR(m.mean_speed_dps, 50.9, 0.2);
  EXPECT_LE(m.max_distance_m, 0.05);
  EXPECT_GT(m.max_distance_m, 0.02);
}

TEST(SynthFastRotation, StartsAtTheBasePose) {
  const Scenario s = MakeScenario("fast_rotation", 3);
  const Eigen::Isometry3d T_world_camera = CameraPoseAt(s.camera, 0.0, s.seed);
  EXPECT_EQ(T_world_camera.translation(), s.camera.position_m);
  EXPECT_EQ(T_world_camera.linear(), LookAtRotation(s.camera.position_m, s.camera.look_at_m));
}

TEST(SynthFastRotation, OtherScenariosAreSharpAndWithoutHandShake) {
  for (const auto& [name, description] : ScenarioNames()) {
    if (name == "fast_rotation" || name == "fast_rotation_kinect") continue;
    const Scenario s = MakeScenario(name, 1);
    EXPECT_EQ(s.camera.exposure.exposure_s, 0.0) << name;
    EXPECT_EQ(s.camera.rpy_translation_m, Eigen::Vector3d::Zero()) << name;
  }
}

}  // namespace
}  // namespace synth
}  // namespace dslam
