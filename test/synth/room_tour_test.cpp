// Tests of the scenario `room_tour` (scenario.h, tour_motion.h): the camera walks a closed path of
// 8-12 m round the room at 0.3-0.5 m/s, comes back within 0.1 m and 10 deg of its first views, and
// two walkers cross its view (none in the first 6 frames), one of them on the same stretch in the
// first lap and again after it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dslam/synth/sequence.h"

namespace dslam {
namespace synth {
namespace {

double AngleDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.rotation().transpose() * b.rotation()).angle() * 180.0 / M_PI;
}

/// Whether the walker's chest (1.2 m above its floor point) is in the image of the camera at
/// `T_world_camera`, between 0.5 and 6 m ahead.
bool InView(const Scenario& s, const WalkerParams& w, double t_s,
            const Eigen::Isometry3d& T_world_camera) {
  const WalkerState state = WalkerStateAt(w, t_s);
  const Eigen::Vector3d chest(state.position_m.x(), state.position_m.y(), 1.2);
  const Eigen::Vector3d p = T_world_camera.inverse() * chest;
  if (p.z() < 0.5 || p.z() > 6.0) return false;
  const double u = s.sensor.fx * p.x() / p.z() + s.sensor.cx;
  const double v = s.sensor.fy * p.y() / p.z() + s.sensor.cy;
  return u >= 0 && u < s.sensor.width && v >= 0 && v < s.sensor.height;
}

TEST(SynthRoomTour, OneLapOfEightToTwelveMetresAtWalkingPace) {
  for (uint32_t seed : {1u, 4u}) {
    const Scenario s = MakeScenario("room_tour", seed);
    const double lap_s = TourLapTime(s.camera.tour);
    EXPECT_GE(TourLapLength(s.camera.tour), 8.0);
    EXPECT_LE(TourLapLength(s.camera.tour), 12.0);
    // The camera centre's own path over the lap (bob and sway included), frame by frame.
    double path_m = 0.0;
    const int lap_frames = static_cast<int>(lap_s * s.fps);
    for (int i = 1; i <= lap_frames; ++i) {
      path_m += (CameraPoseAt(s.camera, i / s.fps, seed).translation() -
                 CameraPoseAt(s.camera, (i - 1) / s.fps, seed).translation())
                    .norm();
    }
    EXPECT_GT(path_m / (lap_frames / s.fps), 0.3);
    EXPECT_LT(path_m / (lap_frames / s.fps), 0.5);
    // The sequence goes on past the lap, into the first views again.
    EXPECT_GE(s.frames / s.fps, lap_s + 2.0);
  }
}

TEST(SynthRoomTour, ReturnsToItsFirstViews) {
  for (uint32_t seed : {1u, 2u, 3u, 4u, 5u}) {
    const Scenario s = MakeScenario("room_tour", seed);
    const double lap_s = TourLapTime(s.camera.tour);
    for (double t : {0.0, 0.5, 1.0, 2.0}) {
      const Eigen::Isometry3d a = CameraPoseAt(s.camera, t, seed);
      const Eigen::Isometry3d b = CameraPoseAt(s.camera, t + lap_s, seed);
      EXPECT_LT((a.translation() - b.translation()).norm(), 0.1) << "seed " << seed << " t " << t;
      EXPECT_LT(AngleDeg(a, b), 10.0) << "seed " << seed << " t " << t;
    }
    // Half a lap on, the camera is far from there and looks elsewhere.
    const Eigen::Isometry3d half = CameraPoseAt(s.camera, 0.5 * lap_s, seed);
    EXPECT_GT((half.translation() - CameraPoseAt(s.camera, 0.0, seed).translation()).norm(), 2.0);
    EXPECT_GT(AngleDeg(half, CameraPoseAt(s.camera, 0.0, seed)), 90.0);
  }
}

TEST(SynthRoomTour, WalkersCrossTheViewAndOneRepeatsItsStretch) {
  for (uint32_t seed : {1u, 2u, 3u, 4u, 5u}) {
    const Scenario s = MakeScenario("room_tour", seed);
    ASSERT_EQ(s.walkers.size(), 2u);
    const double lap_s = TourLapTime(s.camera.tour);
    std::vector<int> frames_in_view(2, 0);
    int first_frames = 0, side_first_lap = 0, side_after_lap = 0;
    double nearest_m = INFINITY;
    for (int i = 0; i < s.frames; ++i) {
      const double t = i / s.fps;
      const Eigen::Isometry3d T_world_camera = CameraPoseAt(s.camera, t, seed);
      for (int k = 0; k < 2; ++k) {
        const WalkerState w = WalkerStateAt(s.walkers[k], t);
        nearest_m =
            std::min(nearest_m, (w.position_m - T_world_camera.translation().head<2>()).norm());
        if (!InView(s, s.walkers[k], t, T_world_camera)) continue;
        ++frames_in_view[k];
        if (i < 6) ++first_frames;
        if (k == 1) ++(t < lap_s ? side_first_lap : side_after_lap);
        // Walker 2 is where it was one lap earlier (and will be one lap later).
        if (k == 1) {
          EXPECT_LT((WalkerStateAt(s.walkers[k], t + lap_s).position_m - w.position_m).norm(),
                    1e-6);
        }
      }
    }
    EXPECT_GE(frames_in_view[0], 30) << "seed " << seed;
    EXPECT_EQ(first_frames, 0) << "seed " << seed;  // the first map is made without people
    EXPECT_GE(side_first_lap, 15) << "seed " << seed;
    EXPECT_GE(side_after_lap, 15) << "seed " << seed;
    EXPECT_GT(nearest_m, 0.5) << "seed " << seed;  // nobody walks into the camera
  }
}

}  // namespace
}  // namespace synth
}  // namespace dslam
