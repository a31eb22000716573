// LocalMappingJob: the back end's run on a copy of the window must leave the map exactly as the
// same run in place, and must only touch keyframes and points that are still in the map when its
// results are applied (tracking changes the map meanwhile in threaded mode).
#include "dslam/backend/local_mapping_job.h"

#include <random>

#include <gtest/gtest.h>

#include "dslam/backend/local_bundle_adjustment.h"
#include "dslam/backend/window_static_points.h"

namespace dslam {
namespace {

constexpr int kKeyFrames = 6, kStatic = 60, kMoving = 12;

// Keyframes along x measure 60 static points and a cluster of 12 points that moves 5 cm per
// keyframe (measurement noise 2 mm across, 1 cm along z); poses but the first perturbed.
Map MakeMap(unsigned seed) {
  Map map;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<Eigen::Vector3d> truth;
  for (int i = 0; i < kStatic + kMoving; ++i) {
    const Eigen::Vector3d p = i < kStatic ? Eigen::Vector3d(1.5 * u(rng), u(rng), 3.0 + u(rng))
                                          : Eigen::Vector3d(0.2 * u(rng), 0.2 * u(rng), 2.5);
    truth.push_back(p);
    MapPoint point;
    point.p_world = p + Eigen::Vector3d(n(rng), n(rng), n(rng)) * 0.005;
    map.AddPoint(point);
  }
  const Eigen::Vector3d sigma(0.002, 0.002, 0.01);
  for (int k = 0; k < kKeyFrames; ++k) {
    Eigen::Isometry3d T_true = Eigen::Isometry3d::Identity();
    T_true.translation() = Eigen::Vector3d(-0.05 * k, 0.0, 0.0);  // T_camera_world
    Eigen::Isometry3d T = T_true;
    if (k > 0) T.translation() += Eigen::Vector3d(n(rng), n(rng), n(rng)) * 0.01;
    KeyFrame keyframe;
    keyframe.measurements.T_camera_world = T;
    keyframe.T_world_camera = T.inverse();
    for (int i = 0; i < kStatic + kMoving; ++i) {
      const Eigen::Vector3d p_true =
          truth[i] + (i < kStatic ? 0.0 : 0.05 * k) * Eigen::Vector3d::UnitX();
      PointMeasurement m;
      m.covariance = sigma.cwiseAbs2().asDiagonal();
      m.y_camera = T_true * p_true + Eigen::Vector3d(n(rng), n(rng), n(rng)).cwiseProduct(sigma);
      keyframe.measurements.by_point.emplace(i, m);
      keyframe.points.push_back(i);
    }
    map.AddKeyFrame(std::move(keyframe), 100);
  }
  return map;
}

Config TestConfig() {
  Config config;
  config.backend.ba_fixed_keyframes = 1;
  config.backend.ba_max_correction_m = 100.0;
  config.backend.ba_max_correction_deg = 180.0;
  return config;
}

TEST(LocalMappingJob, CopyRunApplyEqualsTheRunInPlace) {
  const Config config = TestConfig();
  Map in_place = MakeMap(3), live = MakeMap(3);
  DetermineStaticPointsInWindow(config, &in_place);
  LocalBundleAdjustment(config, &in_place);
  LocalMappingJob job(live, 7);
  job.Run(config);
  job.Apply(&live);
  EXPECT_EQ(job.generation(), 7u);
  EXPECT_EQ(job.newest_keyframe_id(), kKeyFrames - 1);
  EXPECT_TRUE(job.moved_keyframes());
  EXPECT_GT(job.status().spd_unmarked, 0);  // the moving cluster
  for (int k = 0; k < kKeyFrames; ++k) {
    EXPECT_TRUE(live.keyframes()[k].T_world_camera.matrix() ==
                in_place.keyframes()[k].T_world_camera.matrix())
        << k;
  }
  int unmarked = 0;
  for (PointId id = 0; id < kStatic + kMoving; ++id) {
    EXPECT_TRUE(live.Find(id)->p_world == in_place.Find(id)->p_world) << id;
    EXPECT_EQ(live.Find(id)->marked, in_place.Find(id)->marked) << id;
    EXPECT_EQ(live.Find(id)->dynamic_frames, in_place.Find(id)->dynamic_frames) << id;
    unmarked += !live.Find(id)->marked;
  }
  EXPECT_EQ(unmarked, job.status().spd_unmarked);
}

TEST(LocalMappingJob, ApplySkipsWhatLeftTheMapMeanwhile) {
  const Config config = TestConfig();
  Map live = MakeMap(4);
  LocalMappingJob job(live, 0);
  // Tracking goes on: a point is culled, a new keyframe pushes the oldest out of the window.
  live.Erase(5);
  KeyFrame newest;
  newest.T_world_camera.translation() = Eigen::Vector3d(9.0, 9.0, 9.0);
  const int newest_id = live.AddKeyFrame(newest, kKeyFrames).id;
  job.Run(config);
  job.Apply(&live);
  EXPECT_EQ(live.Find(5), nullptr);  // not brought back
  EXPECT_EQ(live.FindKeyFrame(0), nullptr);
  EXPECT_TRUE(live.FindKeyFrame(newest_id)->T_world_camera.translation().isApprox(
      Eigen::Vector3d(9.0, 9.0, 9.0)));
  // The others were refined: keyframe 2 moved from its perturbed start.
  Map untouched = MakeMap(4);
  EXPECT_FALSE(live.FindKeyFrame(2)->T_world_camera.isApprox(
      untouched.FindKeyFrame(2)->T_world_camera, 1e-9));
}

}  // namespace
}  // namespace dslam
