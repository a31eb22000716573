// Known-answer tests of the local bundle adjustment: keyframes at known poses measure known
// points with noise drawn from each measurement's covariance; perturbed poses and points must
// come back to the truth, outliers must be dropped, and only verified static points may move.
#include "dslam/backend/local_bundle_adjustment.h"

#include <random>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

namespace dslam {
namespace {

struct Scene {
  Map map;
  std::vector<Eigen::Isometry3d> T_camera_world_true;
  std::vector<Eigen::Vector3d> p_world_true;  // by point id
};

Eigen::Isometry3d TruePose(int k) {
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  T_world_camera.linear() = Eigen::AngleAxisd(0.05 * k, Eigen::Vector3d::UnitY()).matrix();
  T_world_camera.translation() = Eigen::Vector3d(0.1 * k, 0.02 * k, 0.0);
  return T_world_camera.inverse();
}

Eigen::Isometry3d Perturbed(const Eigen::Isometry3d& T, std::mt19937* rng, double rad, double m) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Isometry3d out = T;
  const Eigen::Vector3d w(n(*rng) * rad, n(*rng) * rad, n(*rng) * rad);
  out.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()).matrix() * T.linear();
  out.translation() += Eigen::Vector3d(n(*rng), n(*rng), n(*rng)) * m;
  return out;
}

// `keyframes` keyframes measuring `points` verified static points (depth noise 1 cm along z,
// 2 mm across), with the keyframe poses (but the first) and points perturbed.
Scene MakeScene(int keyframes, int points, unsigned seed) {
  Scene scene;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int i = 0; i < points; ++i) {
    MapPoint point;
    point.p_world = Eigen::Vector3d(1.5 * u(rng), u(rng), 3.0 + u(rng));
    scene.p_world_true.push_back(point.p_world);
    point.p_world += Eigen::Vector3d(n(rng), n(rng), n(rng)) * 0.01;
    scene.map.AddPoint(point);
  }
  const Eigen::Vector3d sigma(0.002, 0.002, 0.01);
  for (int k = 0; k < keyframes; ++k) {
    KeyFrame keyframe;
    const Eigen::Isometry3d T_true = TruePose(k);
    scene.T_camera_world_true.push_back(T_true);
    const Eigen::Isometry3d T = k == 0 ? T_true : Perturbed(T_true, &rng, 0.01, 0.02);
    keyframe.measurements.T_camera_world = T;
    keyframe.T_world_camera = T.inverse();
    for (int i = 0; i < points; ++i) {
      PointMeasurement m;
      m.covariance = sigma.cwiseAbs2().asDiagonal();
      m.y_camera = T_true * scene.p_world_true[i] +
                   Eigen::Vector3d(n(rng), n(rng), n(rng)).cwiseProduct(sigma);
      keyframe.measurements.by_point.emplace(i, m);
      keyframe.points.push_back(i);
    }
    scene.map.AddKeyFrame(std::move(keyframe), KeyFrameMapLimits::Newest(100));
  }
  return scene;
}

double RotationErrorRad(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.rotation() * b.rotation().transpose()).angle();
}

// Sum of squared Mahalanobis errors of the keyframes' measurements at the given poses/points.
double Cost(const Map& map, const std::vector<Eigen::Isometry3d>& T_camera_world,
            const std::vector<Eigen::Vector3d>& p_world) {
  double cost = 0.0;
  for (size_t k = 0; k < map.window().size(); ++k) {
    for (const auto& [id, m] : map.window()[k].measurements.by_point) {
      const Eigen::Vector3d e = T_camera_world[k] * p_world[id] - m.y_camera;
      cost += e.dot(m.covariance.inverse() * e);
    }
  }
  return cost;
}

// Only the first keyframe is at its true pose, and moves of up to ~6 cm from the perturbed start
// are expected: one fixed keyframe, no correction limit.
Config Unlimited() {
  Config config;
  config.backend.ba_fixed_keyframes = 1;
  config.backend.ba_max_correction_m = 100.0;
  config.backend.ba_max_correction_deg = 180.0;
  return config;
}

TEST(LocalBundleAdjustment, RecoversPerturbedPosesAndPoints) {
  Scene scene = MakeScene(5, 80, 1);
  const LocalBaStats stats = LocalBundleAdjustment(Unlimited(), &scene.map);
  ASSERT_TRUE(stats.ran);
  EXPECT_EQ(stats.keyframes, 4);
  EXPECT_EQ(stats.fixed_keyframes, 1);
  EXPECT_EQ(stats.points, 80);
  EXPECT_EQ(stats.measurements, 400);
  EXPECT_LE(stats.outliers, 20);  // chi-square 95%: about 5% of the measurements
  // The noise is drawn from the measurements' covariances: the model fits.
  EXPECT_NEAR(stats.chi2_per_dof, 1.0, 0.15);
  EXPECT_LT(stats.inlier_chi2_per_dof, stats.chi2_per_dof);  // the 5 % tail left out
  // Perturbed by 10 mrad and 20 mm per axis; what remains is the estimation error of this
  // geometry (rotation and translation across the view are hard to tell apart at 2-4 m).
  std::vector<Eigen::Isometry3d> T_estimated;
  for (int k = 0; k < 5; ++k) {
    const Eigen::Isometry3d& T = scene.map.window()[k].measurements.T_camera_world;
    EXPECT_LT((T.translation() - scene.T_camera_world_true[k].translation()).norm(), 0.006) << k;
    EXPECT_LT(RotationErrorRad(T, scene.T_camera_world_true[k]), 0.002) << k;
    EXPECT_TRUE(scene.map.window()[k].T_world_camera.isApprox(T.inverse(), 1e-12));
    T_estimated.push_back(T);
  }
  std::vector<Eigen::Vector3d> p_estimated;
  double point_error = 0.0;
  for (int i = 0; i < 80; ++i) {
    p_estimated.push_back(scene.map.Find(i)->p_world);
    point_error += (p_estimated.back() - scene.p_world_true[i]).norm() / 80.0;
  }
  EXPECT_LT(point_error, 0.006);  // started at ~0.016 m (1 cm per axis)
  // The least-squares solution fits the kept measurements at least as well as the truth does.
  EXPECT_LE(Cost(scene.map, T_estimated, p_estimated),
            Cost(scene.map, scene.T_camera_world_true, scene.p_world_true) + 1e-6);
}

TEST(LocalBundleAdjustment, FirstKeyFrameStaysFixed) {
  Scene scene = MakeScene(4, 50, 2);
  const Eigen::Isometry3d before = scene.map.window()[0].measurements.T_camera_world;
  LocalBundleAdjustment(Unlimited(), &scene.map);
  EXPECT_TRUE(scene.map.window()[0].measurements.T_camera_world.isApprox(before, 1e-12));
}

TEST(LocalBundleAdjustment, LeavesOutOutliersButKeepsThem) {
  Scene scene = MakeScene(5, 60, 3);
  const Config config = Unlimited();
  KeyFrame& keyframe = scene.map.mutable_window()[3];
  keyframe.measurements.by_point.at(7).y_camera += Eigen::Vector3d(0.0, 0.2, 0.3);
  const LocalBaStats stats = LocalBundleAdjustment(config, &scene.map);
  EXPECT_GE(stats.outliers, 1);
  EXPECT_LE(stats.outliers, 20);  // chi-square 95%: about 5% of 300 good measurements
  // Kept in the keyframe: static point determination uses it as evidence of motion.
  EXPECT_EQ(scene.map.window()[3].measurements.by_point.count(7), 1u);
  EXPECT_LT((scene.map.Find(7)->p_world - scene.p_world_true[7]).norm(), 0.01);
}

TEST(LocalBundleAdjustment, UnverifiedPointsFollowTheirNewestKeyFrame) {
  Scene scene = MakeScene(4, 40, 4);
  scene.map.Find(0)->marked = false;    // seen moving
  scene.map.Find(1)->candidate = true;  // not yet verified
  const Eigen::Vector3d p0 = scene.map.Find(0)->p_world, p1 = scene.map.Find(1)->p_world;
  const Eigen::Isometry3d T_camera_world_before =
      scene.map.window()[3].measurements.T_camera_world;
  const LocalBaStats stats = LocalBundleAdjustment(Unlimited(), &scene.map);
  EXPECT_EQ(stats.points, 38);
  // Not optimised, but carried with keyframe 3 (the newest that measured them).
  const Eigen::Isometry3d correction =
      scene.map.window()[3].T_world_camera * T_camera_world_before;
  EXPECT_FALSE(correction.isApprox(Eigen::Isometry3d::Identity(), 1e-6));
  EXPECT_TRUE(scene.map.Find(0)->p_world.isApprox(correction * p0, 1e-12));
  EXPECT_TRUE(scene.map.Find(1)->p_world.isApprox(correction * p1, 1e-12));
}

TEST(LocalBundleAdjustment, LargeCorrectionsAreNotApplied) {
  Scene scene = MakeScene(5, 60, 6);
  Config config = Unlimited();
  config.backend.ba_max_correction_m =
      0.001;  // the perturbation is ~35 mm: the solution moves more
  const Eigen::Isometry3d before = scene.map.window()[4].T_world_camera;
  const Eigen::Vector3d p = scene.map.Find(5)->p_world;
  const LocalBaStats stats = LocalBundleAdjustment(config, &scene.map);
  EXPECT_TRUE(stats.ran);
  EXPECT_TRUE(stats.rejected);
  EXPECT_GT(stats.largest_correction_m, 0.001);
  EXPECT_TRUE(scene.map.window()[4].T_world_camera.isApprox(before, 0.0));
  EXPECT_EQ(scene.map.Find(5)->p_world, p);
}

TEST(LocalBundleAdjustment, TooFewKeyFramesChangeNothing) {
  Scene scene = MakeScene(1, 30, 5);
  const Eigen::Vector3d p = scene.map.Find(3)->p_world;
  EXPECT_FALSE(LocalBundleAdjustment(Config(), &scene.map).ran);
  EXPECT_EQ(scene.map.Find(3)->p_world, p);
}

}  // namespace
}  // namespace dslam
