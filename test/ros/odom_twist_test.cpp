// OdomTwist: the base frame's velocity between two frames tracked in a row (and unknown after a
// gap), its covariance from the two poses' information, and the Jacobian from the pose solver's
// perturbation to the base frame's, checked against finite differences.
#include <cmath>

#include <gtest/gtest.h>

#include "dslam/ros/odom_twist.h"

namespace dslam {
namespace {

using ros_layer::BasePerturbationFromSolver;
using ros_layer::Matrix6d;
using ros_layer::OdomTwist;
using ros_layer::Vector6d;

constexpr double kDt = 1.0 / 30.0;

// A camera moving forward (optical z) 5 cm per frame while turning 1 deg about optical y.
Eigen::Isometry3d Step() {
  return Eigen::Translation3d(0.002, -0.001, 0.05) *
         Eigen::AngleAxisd(M_PI / 180.0, Eigen::Vector3d::UnitY());
}

// REP 103 base (x forward, y left, z up) from the optical frame (z forward, x right, y down).
Eigen::Isometry3d BaseFromOptical() {
  Eigen::Matrix3d R;
  R << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  return T;
}

FrameResult Tracked(int frame, const Eigen::Isometry3d& T_world_camera, bool from_previous) {
  FrameResult r;
  r.has_pose = true;
  r.has_previous_pose = from_previous;
  r.stamp_s = 100.0 + frame * kDt;
  r.T_world_camera = T_world_camera;
  return r;
}

void ExpectUnknown(const OdomTwist& twist) {
  EXPECT_FALSE(twist.known());
  EXPECT_TRUE(twist.velocity().isZero());
  EXPECT_TRUE(twist.covariance().isApprox(OdomTwist::kUnknownVariance * Matrix6d::Identity()));
}

TEST(OdomTwist, ConstantMotionGivesItsVelocityInTheBaseFrame) {
  OdomTwist twist;
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  twist.Add(Tracked(0, T_world_camera, false), T_world_camera, BaseFromOptical());
  ExpectUnknown(twist);  // one frame: no motion yet
  for (int i = 1; i < 5; ++i) {
    T_world_camera = T_world_camera * Step();
    twist.Add(Tracked(i, T_world_camera, true), T_world_camera, BaseFromOptical());
    ASSERT_TRUE(twist.known()) << i;
    Vector6d expected;  // optical z -> base x, optical x -> base -y, optical y -> base -z
    expected << 0.05 / kDt, -0.002 / kDt, 0.001 / kDt, 0.0, 0.0, -M_PI / 180.0 / kDt;
    EXPECT_LT((twist.velocity() - expected).norm(), 1e-9) << twist.velocity().transpose();
  }
}

TEST(OdomTwist, UnknownAfterAGapARelocalisedPoseOrAStampNotAfterThePrevious) {
  OdomTwist twist;
  const Eigen::Isometry3d T0 = Eigen::Isometry3d::Identity();
  const Eigen::Isometry3d T1 = Step();
  twist.Add(Tracked(0, T0, false), T0, BaseFromOptical());
  FrameResult lost;
  lost.stamp_s = 100.0 + kDt;
  twist.Add(lost, T0, BaseFromOptical());
  ExpectUnknown(twist);
  twist.Add(Tracked(2, T1, true), T1, BaseFromOptical());  // the frame before had no pose
  ExpectUnknown(twist);
  twist.Add(Tracked(3, T1 * Step(), false), T1 * Step(), BaseFromOptical());  // relocalised
  ExpectUnknown(twist);
  twist.Add(Tracked(3, T1 * Step() * Step(), true), T1 * Step() * Step(), BaseFromOptical());
  ExpectUnknown(twist);  // the same stamp: no time between them
  twist.Add(Tracked(5, T1 * Step() * Step(), true), T1 * Step() * Step(), BaseFromOptical());
  EXPECT_TRUE(twist.known());
  twist.Restart();
  twist.Add(Tracked(6, T1, true), T1, BaseFromOptical());
  ExpectUnknown(twist);
}

// The solver's perturbation of T_camera_world applied to a pose, against the base frame's own
// perturbation the Jacobian predicts, one column at a time.
TEST(OdomTwist, BasePerturbationMatchesFiniteDifferences) {
  const Eigen::Isometry3d T_camera_world =
      Eigen::Translation3d(0.4, -1.2, 2.5) *
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, 1.0, -0.4).normalized());
  const Eigen::Isometry3d T_base_camera =
      Eigen::Translation3d(0.1, 0.02, 0.3) * BaseFromOptical() *
      Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX());
  const Matrix6d J = BasePerturbationFromSolver(T_camera_world, T_base_camera);
  const Eigen::Isometry3d T_world_base = T_camera_world.inverse() * T_base_camera.inverse();
  constexpr double kH = 1e-7;
  for (int k = 0; k < 6; ++k) {
    Eigen::Isometry3d perturbed = T_camera_world;
    if (k < 3) {
      perturbed.linear() =
          Eigen::AngleAxisd(kH, Eigen::Vector3d::Unit(k)).toRotationMatrix() *
          T_camera_world.linear();
    } else {
      perturbed.translation() += kH * Eigen::Vector3d::Unit(k - 3);
    }
    const Eigen::Isometry3d delta =
        T_world_base.inverse() * (perturbed.inverse() * T_base_camera.inverse());
    const Eigen::AngleAxisd rotation(delta.rotation());
    Vector6d numeric;
    numeric << delta.translation() / kH, rotation.angle() * rotation.axis() / kH;
    EXPECT_LT((numeric - J.col(k)).norm(), 1e-5 * (1.0 + J.col(k).norm()))
        << "column " << k << ": " << numeric.transpose() << " against " << J.col(k).transpose();
  }
}

// At the world origin with the base the optical frame, the solver's [dtheta, dt] information is
// the base's [rho, phi] covariance reordered; the twist's covariance sums two frames' over dt^2.
TEST(OdomTwist, CovarianceSumsBothPosesOverDtSquared) {
  OdomTwist twist;
  FrameResult first = Tracked(0, Eigen::Isometry3d::Identity(), false);
  Vector6d information;
  information << 1e4, 2e4, 4e4, 1e6, 2e6, 4e6;  // [dtheta (rad^-2), dt (m^-2)]
  first.information = information.asDiagonal();
  twist.Add(first, Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity());
  FrameResult second = Tracked(1, Eigen::Isometry3d::Identity(), true);
  second.information = information.asDiagonal();
  twist.Add(second, Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity());
  ASSERT_TRUE(twist.known());
  Vector6d variance;  // [rho, phi] from [dt, dtheta]
  variance << 1e-6, 0.5e-6, 0.25e-6, 1e-4, 0.5e-4, 0.25e-4;
  const Matrix6d expected = Matrix6d(variance.asDiagonal()) * 2.0 / (kDt * kDt);
  EXPECT_LT((twist.covariance() - expected).norm(), 1e-9 * expected.norm())
      << twist.covariance();
  FrameResult without = Tracked(2, Eigen::Isometry3d::Identity(), true);  // no information
  twist.Add(without, Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity());
  EXPECT_TRUE(twist.known());
  EXPECT_TRUE(
      twist.covariance().isApprox(OdomTwist::kUnknownVariance * Matrix6d::Identity()));
}

}  // namespace
}  // namespace dslam
