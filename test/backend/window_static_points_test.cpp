// Known-answer tests of back-end static point determination (Algorithm 1 over the window):
// keyframes at known poses measure a static room and a box that moves slowly between keyframes
// (1 cm per keyframe: within the noise of any two adjacent keyframes, far outside it over the
// window), with noise drawn from each measurement's covariance (seeded).
#include "dslam/backend/window_static_points.h"

#include <random>

#include <gtest/gtest.h>

namespace dslam {
namespace {

constexpr double kSigmaXy = 0.002, kSigmaZ = 0.006;  // [m] measurement noise, camera frame

Eigen::Isometry3d TrueCameraWorld(int k) {
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  T_world_camera.linear() = Eigen::AngleAxisd(0.03 * k, Eigen::Vector3d::UnitY()).matrix();
  T_world_camera.translation() = Eigen::Vector3d(0.05 * k, 0.0, 0.0);
  return T_world_camera.inverse();
}

struct Scene {
  Map map;
  std::vector<PointId> static_ids, moving_ids;
};

// `keyframes` keyframes; 200 static points spread over a room and 40 on a 40 cm box that moves
// along x by `box_step_m` per keyframe. Every keyframe measures every point.
Scene MakeScene(int keyframes, double box_step_m, unsigned seed) {
  Scene scene;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<Eigen::Vector3d> p_world;
  for (int i = 0; i < 240; ++i) {
    const bool moving = i >= 200;
    MapPoint point;
    point.p_world = moving ? Eigen::Vector3d(0.2 * u(rng), 0.2 * u(rng), 2.0 + 0.2 * u(rng))
                           : Eigen::Vector3d(2.0 * u(rng), 1.5 * u(rng), 4.0 + u(rng));
    p_world.push_back(point.p_world);
    (moving ? scene.moving_ids : scene.static_ids).push_back(scene.map.AddPoint(point));
  }
  const Eigen::Vector3d sigma(kSigmaXy, kSigmaXy, kSigmaZ);
  for (int k = 0; k < keyframes; ++k) {
    KeyFrame keyframe;
    keyframe.frame_index = 10 * k;
    keyframe.measurements.T_camera_world = TrueCameraWorld(k);
    keyframe.T_world_camera = keyframe.measurements.T_camera_world.inverse();
    for (size_t i = 0; i < p_world.size(); ++i) {
      const PointId id = static_cast<PointId>(i);
      const bool moving = i >= 200;
      const Eigen::Vector3d p = p_world[i] + Eigen::Vector3d(moving ? box_step_m * k : 0.0, 0, 0);
      PointMeasurement m;
      m.covariance = sigma.cwiseAbs2().asDiagonal();
      m.y_camera = keyframe.measurements.T_camera_world * p +
                   Eigen::Vector3d(n(rng) * kSigmaXy, n(rng) * kSigmaXy, n(rng) * kSigmaZ);
      keyframe.measurements.by_point.emplace(id, m);
      keyframe.points.push_back(id);
    }
    scene.map.AddKeyFrame(keyframe, KeyFrameMapLimits::Newest(100));
  }
  return scene;
}

int CountMarked(const Map& map, const std::vector<PointId>& ids) {
  int marked = 0;
  for (PointId id : ids) marked += map.Find(id)->marked;
  return marked;
}

TEST(WindowStaticPoints, UnmarksASlowBoxThatTwoKeyFramesCannotSee) {
  const Config config;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    // Two keyframes: 1 cm between them is below the test's resolution; the box stays marked.
    Scene pair = MakeScene(2, 0.01, seed);
    const WindowStaticPointsStats two = DetermineStaticPointsInWindow(config, &pair.map);
    ASSERT_TRUE(two.ran);
    EXPECT_GT(CountMarked(pair.map, pair.moving_ids), 30) << "seed " << seed;
    // Twelve keyframes: 11 cm over the window; every box point loses its mark.
    Scene window = MakeScene(12, 0.01, seed);
    const WindowStaticPointsStats stats = DetermineStaticPointsInWindow(config, &window.map);
    ASSERT_TRUE(stats.ran);
    EXPECT_EQ(stats.keyframes, 12);
    EXPECT_EQ(stats.graph.points, 240);
    EXPECT_EQ(CountMarked(window.map, window.moving_ids), 0) << "seed " << seed;
    EXPECT_GE(CountMarked(window.map, window.static_ids), 198) << "seed " << seed;
    EXPECT_GT(stats.graph.culled_edges, 0);
    EXPECT_EQ(stats.unmarked, 240 - CountMarked(window.map, window.static_ids) -
                                  CountMarked(window.map, window.moving_ids));
  }
}

TEST(WindowStaticPoints, StaticSceneKeepsItsMarks) {
  const Config config;
  int unmarked = 0;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    Scene scene = MakeScene(12, 0.0, seed);
    ASSERT_TRUE(DetermineStaticPointsInWindow(config, &scene.map).ran);
    unmarked +=
        240 - CountMarked(scene.map, scene.static_ids) - CountMarked(scene.map, scene.moving_ids);
  }
  EXPECT_LE(unmarked, 7);  // 1% of 720: the test's false alarms at probability 0.99
}

TEST(WindowStaticPoints, UnmarkedPointsStayOutAndNeedRemarkFramesToComeBack) {
  Config config;
  Scene scene = MakeScene(12, 0.01, 4);
  for (PointId id : scene.moving_ids) scene.map.Find(id)->marked = false;
  const WindowStaticPointsStats stats = DetermineStaticPointsInWindow(config, &scene.map);
  EXPECT_EQ(stats.graph.points, 200);  // only marked points enter (Algorithm 1: the static set)
  EXPECT_LE(stats.unmarked, 2);

  Scene moving = MakeScene(12, 0.01, 5);
  DetermineStaticPointsInWindow(config, &moving.map);
  for (PointId id : moving.moving_ids) {
    const MapPoint* point = moving.map.Find(id);
    EXPECT_FALSE(point->candidate);
    EXPECT_GE(point->dynamic_frames, config.tracking.remark_frames);
  }
}

TEST(WindowStaticPoints, NeedsTwoKeyFramesAndCovisibility) {
  Config config;
  Scene one = MakeScene(1, 0.01, 6);
  EXPECT_FALSE(DetermineStaticPointsInWindow(config, &one.map).ran);
  Scene scene = MakeScene(12, 0.01, 7);
  // The newest keyframe keeps 10 measurements: every other keyframe shares fewer than 20 with it.
  auto& newest = scene.map.mutable_keyframes().back().measurements.by_point;
  for (PointId id = 10; id < 240; ++id) newest.erase(id);
  EXPECT_FALSE(DetermineStaticPointsInWindow(config, &scene.map).ran);
  EXPECT_EQ(CountMarked(scene.map, scene.moving_ids), 40);
}

}  // namespace
}  // namespace dslam
