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
    map.AddKeyFrame(std::move(keyframe), KeyFrameMapLimits::Newest(100));
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
  EXPECT_GT(job.status().spd.unmarked, 0);  // the moving cluster
  for (int k = 0; k < kKeyFrames; ++k) {
    EXPECT_TRUE(live.window()[k].T_world_camera.matrix() ==
                in_place.window()[k].T_world_camera.matrix())
        << k;
  }
  int unmarked = 0;
  for (PointId id = 0; id < kStatic + kMoving; ++id) {
    EXPECT_TRUE(live.Find(id)->p_world == in_place.Find(id)->p_world) << id;
    EXPECT_EQ(live.Find(id)->marked, in_place.Find(id)->marked) << id;
    EXPECT_EQ(live.Find(id)->dynamic_frames, in_place.Find(id)->dynamic_frames) << id;
    unmarked += !live.Find(id)->marked;
  }
  EXPECT_EQ(unmarked, job.status().spd.unmarked);
}

TEST(LocalMappingJob, ApplySkipsWhatLeftTheMapMeanwhile) {
  const Config config = TestConfig();
  Map live = MakeMap(4);
  LocalMappingJob job(live, 0);
  // Tracking goes on: a point is culled, a new keyframe pushes the oldest out of the window.
  live.Erase(5);
  KeyFrame newest;
  newest.T_world_camera.translation() = Eigen::Vector3d(9.0, 9.0, 9.0);
  const int newest_id = live.AddKeyFrame(newest, KeyFrameMapLimits::Newest(kKeyFrames)).id;
  job.Run(config);
  job.Apply(&live);
  EXPECT_EQ(live.Find(5), nullptr);  // not brought back
  EXPECT_EQ(live.FindKeyFrame(0), nullptr);
  // The keyframe made meanwhile is not refined; it moves with the copied window's newest.
  const Eigen::Isometry3d correction = live.FindKeyFrame(job.newest_keyframe_id())->T_world_camera *
                                       MakeMap(4).window().back().T_world_camera.inverse();
  EXPECT_TRUE(live.FindKeyFrame(newest_id)->T_world_camera.translation().isApprox(
      correction * Eigen::Vector3d(9.0, 9.0, 9.0)));
  // The others were refined: keyframe 2 moved from its perturbed start.
  Map untouched = MakeMap(4);
  EXPECT_FALSE(live.FindKeyFrame(2)->T_world_camera.isApprox(
      untouched.FindKeyFrame(2)->T_world_camera, 1e-9));
}

// In threaded mode tracking goes on while a run works on its copy: what the front end changed
// meanwhile must survive Apply, with the run's own results added to it.
TEST(LocalMappingJob, KeepsWhatTheFrontEndChangedDuringTheRun) {
  Config config = TestConfig();
  config.tracking.remark_frames = 3;
  Map in_place = MakeMap(5), live = MakeMap(5);
  const Map untouched = MakeMap(5);
  DetermineStaticPointsInWindow(config, &in_place);
  LocalBundleAdjustment(config, &in_place);
  LocalMappingJob job(live, 0);
  // Meanwhile the front end found static point 0 moving and re-positioned it, fused a new
  // measurement into static point 1, and labelled moving point kStatic dynamic in 10 frames.
  live.Find(0)->Unmark(0);
  live.Find(0)->p_world = Eigen::Vector3d(7.0, 7.0, 7.0);
  const Eigen::Vector3d fused(0.001, 0.0, 0.0);
  live.Find(1)->p_world += fused;
  for (int frame = 0; frame < 10; ++frame) live.Find(kStatic)->Unmark(0);
  job.Run(config);
  job.Apply(&live);
  ASSERT_NE(in_place.Find(0)->p_world, untouched.Find(0)->p_world);  // the run moved both
  ASSERT_NE(in_place.Find(1)->p_world, untouched.Find(1)->p_world);
  ASSERT_FALSE(in_place.Find(kStatic)->marked);  // and unmarked the moving one
  EXPECT_EQ(live.Find(0)->p_world, Eigen::Vector3d(7.0, 7.0, 7.0));
  EXPECT_FALSE(live.Find(0)->marked);
  EXPECT_TRUE(live.Find(1)->p_world.isApprox(in_place.Find(1)->p_world + fused, 1e-12))
      << live.Find(1)->p_world.transpose();
  EXPECT_FALSE(live.Find(kStatic)->marked);
  EXPECT_EQ(live.Find(kStatic)->dynamic_frames, 11);  // the front end's 10 and the window's one
}

// Keyframes and points made while the run worked are not in its window; they were placed from
// poses tracked against the uncorrected map, so they move with the window's newest keyframe.
TEST(LocalMappingJob, WhatWasMadeDuringTheRunFollowsItsNewestKeyFrame) {
  const Config config = TestConfig();
  Map live = MakeMap(6);
  LocalMappingJob job(live, 0);
  const Eigen::Isometry3d T_world_newest = live.window().back().T_world_camera;
  KeyFrame made;
  made.T_world_camera = T_world_newest * Eigen::Translation3d(0.05, 0.0, 0.01);
  made.measurements.T_camera_world = made.T_world_camera.inverse();
  MapPoint point;
  point.p_world = made.T_world_camera * Eigen::Vector3d(0.1, -0.2, 2.0);
  const PointId point_id = live.AddPoint(point);
  made.points.push_back(point_id);
  const int made_id = live.AddKeyFrame(made, KeyFrameMapLimits::Newest(100)).id;
  job.Run(config);
  job.Apply(&live);
  const Eigen::Isometry3d correction =
      live.FindKeyFrame(job.newest_keyframe_id())->T_world_camera * T_world_newest.inverse();
  ASSERT_GT(correction.translation().norm(), 1e-5);
  const KeyFrame& after = *live.FindKeyFrame(made_id);
  EXPECT_TRUE(after.T_world_camera.isApprox(correction * made.T_world_camera, 1e-12));
  EXPECT_TRUE(after.measurements.T_camera_world.isApprox(after.T_world_camera.inverse(), 1e-12));
  EXPECT_TRUE(live.Find(point_id)->p_world.isApprox(correction * point.p_world, 1e-12));
}

// A re-anchoring (Map::MoveMadeSince) while the run worked: the run's poses and positions are in
// the world before it, so Apply must leave the corrected ones alone; its unmarks still count.
TEST(LocalMappingJob, ACorrectionOfTheMapDuringTheRunKeepsTheCorrectedPoses) {
  const Config config = TestConfig();
  Map live = MakeMap(7);
  LocalMappingJob job(live, 0);
  MapCorrection correction;
  correction.first_frame = 0;  // every keyframe and point of MakeMap
  correction.T_new_old =
      Eigen::Translation3d(0.3, 0.0, -0.1) * Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY());
  live.MoveMadeSince(correction);
  const Map corrected = live;
  job.Run(config);
  ASSERT_TRUE(job.moved_keyframes());
  job.Apply(&live);
  for (const KeyFrame& keyframe : live.window()) {
    const KeyFrame& expected = corrected.window()[keyframe.id];
    EXPECT_TRUE(keyframe.T_world_camera.matrix() == expected.T_world_camera.matrix())
        << keyframe.id;
  }
  int unmarked = 0;
  for (PointId id = 0; id < kStatic + kMoving; ++id) {
    EXPECT_TRUE(live.Find(id)->p_world == corrected.Find(id)->p_world) << id;
    unmarked += !live.Find(id)->marked;
  }
  EXPECT_GT(job.status().spd.unmarked, 0);
  EXPECT_EQ(unmarked, job.status().spd.unmarked);
}

}  // namespace
}  // namespace dslam
