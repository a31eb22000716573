// Tests of the periodic scenario `loop` (scenario.h): the camera pose and all geometry at t and at
// t + period agree, so its frames replay in a loop without a jump; and the motions are not trivial.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dslam/synth/sequence.h"

namespace dslam {
namespace synth {
namespace {

constexpr double kTolerance = 1e-9;  ///< [m] / [-] floating-point noise of sin(2 pi k) etc.

/// Largest difference between the poses and half extents of matching boxes and the vertices of
/// matching triangles of two scenes with the same primitives; infinity when their counts differ.
double GeometryDifference(const SceneGeometry& a, const SceneGeometry& b) {
  if (a.boxes.size() != b.boxes.size() || a.triangles.size() != b.triangles.size()) {
    return INFINITY;
  }
  double diff = 0.0;
  for (size_t i = 0; i < a.boxes.size(); ++i) {
    const Box &p = a.boxes[i], &q = b.boxes[i];
    if (p.object_id != q.object_id || p.material.seed != q.material.seed) return INFINITY;
    diff = std::max(diff, (p.T_world_box.matrix() - q.T_world_box.matrix()).cwiseAbs().maxCoeff());
    diff = std::max(diff, (p.half_extent - q.half_extent).cwiseAbs().maxCoeff());
  }
  for (size_t i = 0; i < a.triangles.size(); ++i) {
    for (int v = 0; v < 3; ++v) {
      diff = std::max(diff,
                      (a.triangles[i].vertex[v] - b.triangles[i].vertex[v]).cwiseAbs().maxCoeff());
    }
  }
  return diff;
}

double PoseDifference(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.matrix() - b.matrix()).cwiseAbs().maxCoeff();
}

TEST(SynthLoop, FramesCoverExactlyOnePeriod) {
  const Scenario s = MakeScenario("loop", 1);
  ASSERT_GT(s.period_s, 0.0);
  EXPECT_DOUBLE_EQ(s.period_s, 20.0);
  EXPECT_EQ(s.frames, 600);
  EXPECT_DOUBLE_EQ(s.frames / s.fps, s.period_s);
  EXPECT_EQ(s.walkers.size(), 3u);
}

TEST(SynthLoop, CameraAndWalkersRepeatAfterThePeriod) {
  const Scenario s = MakeScenario("loop", 2);
  const SyntheticSequence sequence(s);
  // Every 0.37 s over one period, and inside the pauses of the walkers.
  for (double t = 0.0; t <= s.period_s; t += 0.37) {
    EXPECT_LT(PoseDifference(CameraPoseAt(s.camera, t, s.seed),
                             CameraPoseAt(s.camera, t + s.period_s, s.seed)),
              kTolerance)
        << "t = " << t;
    EXPECT_LT(GeometryDifference(sequence.GeometryAtTime(t),
                                 sequence.GeometryAtTime(t + 3.0 * s.period_s)),
              kTolerance)
        << "t = " << t;
  }
  // The seamless join of a replay: frame `frames` is frame 0 again.
  EXPECT_LT(PoseDifference(sequence.PoseOf(s.frames), sequence.PoseOf(0)), kTolerance);
  EXPECT_LT(GeometryDifference(sequence.GeometryAt(s.frames), sequence.GeometryAt(0)), kTolerance);
}

TEST(SynthLoop, WalkersRepeatTheirGaitAndPauses) {
  const Scenario s = MakeScenario("loop", 1);
  for (const WalkerParams& w : s.walkers) {
    EXPECT_GT(w.speed_mps, 0.6);
    EXPECT_LT(w.speed_mps, 1.3);
    EXPECT_NEAR(w.stride_m, 1.4, 0.1);
    for (double t : {0.0, 2.3, 4.9, 7.7, 13.1, 19.9}) {
      const WalkerState a = WalkerStateAt(w, t), b = WalkerStateAt(w, t + s.period_s);
      EXPECT_LT((a.position_m - b.position_m).norm(), kTolerance) << "t = " << t;
      EXPECT_NEAR(std::remainder(a.gait_phase_rad - b.gait_phase_rad, 2.0 * M_PI), 0.0, 1e-6);
      EXPECT_NEAR(a.idle_time_s, b.idle_time_s, 1e-6) << "t = " << t;
    }
  }
}

TEST(SynthLoop, ThingsMoveWithinThePeriod) {
  const Scenario s = MakeScenario("loop", 1);
  const SyntheticSequence sequence(s);
  // Half a period later the camera and every walker are elsewhere.
  EXPECT_GT((sequence.PoseOf(150).translation() - sequence.PoseOf(0).translation()).norm(), 0.3);
  for (const WalkerParams& w : s.walkers) {
    EXPECT_GT(
        (WalkerStateAt(w, 0.5 * s.period_s).position_m - WalkerStateAt(w, 0.0).position_m).norm() +
            (WalkerStateAt(w, 0.3 * s.period_s).position_m - WalkerStateAt(w, 0.0).position_m)
                .norm(),
        0.3);
  }
  // Only `loop` claims a period.
  for (const auto& [name, description] : ScenarioNames()) {
    if (name != "loop") {
      EXPECT_EQ(MakeScenario(name, 1).period_s, 0.0) << name;
    }
  }
}

}  // namespace
}  // namespace synth
}  // namespace dslam
