// OdomIntegrator (REP 105): the back end's corrections between frames, relocalisation and the
// first pose after lost frames go into map -> odom; odom moves only by the tracked motion; with
// nothing corrected map -> odom stays exactly the identity; resets.
#include <cmath>

#include <gtest/gtest.h>

#include "dslam/ros/odom_integrator.h"

namespace dslam {
namespace {

using ros_layer::OdomIntegrator;

// A camera moving forward (optical z) 5 cm per frame while turning 1 deg about optical y.
Eigen::Isometry3d Step() {
  return Eigen::Translation3d(0.002, -0.001, 0.05) *
         Eigen::AngleAxisd(M_PI / 180.0, Eigen::Vector3d::UnitY());
}

// A correction of the kind local BA makes, T_world_new_old (1-2 cm, 0.6 deg).
Eigen::Isometry3d Correction() {
  return Eigen::Translation3d(0.01, -0.02, 0.005) *
         Eigen::AngleAxisd(0.01, Eigen::Vector3d(0.3, 1.0, 0.2).normalized());
}

/// A tracked frame at T_world_camera, tracked on from T_world_previous (none: no previous pose).
FrameResult Tracked(const Eigen::Isometry3d& T_world_camera,
                    const Eigen::Isometry3d* T_world_previous) {
  FrameResult r;
  r.has_pose = true;
  r.state = TrackingState::kTracking;
  r.T_world_camera = T_world_camera;
  r.has_previous_pose = T_world_previous != nullptr;
  if (T_world_previous) r.T_world_previous_camera = *T_world_previous;
  return r;
}

FrameResult Lost() {
  FrameResult r;
  r.state = TrackingState::kLost;
  return r;
}

bool Near(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return a.isApprox(b, 1e-12) || (a.matrix() - b.matrix()).norm() < 1e-12;
}

// Feeds `frames` tracked frames moving by Step() from `T_world_camera` (tracked on from it, as
// tracking reported it); returns the last pose.
Eigen::Isometry3d Track(OdomIntegrator* integrator, Eigen::Isometry3d T_world_camera, int frames) {
  for (int i = 0; i < frames; ++i) {
    const Eigen::Isometry3d previous = T_world_camera;
    T_world_camera = T_world_camera * Step();
    integrator->Add(Tracked(T_world_camera, &previous));
  }
  return T_world_camera;
}

TEST(OdomIntegrator, WithoutCorrectionsOdomIsTheTrackedPoseAndMapOdomExactlyIdentity) {
  OdomIntegrator integrator;
  EXPECT_FALSE(integrator.has_pose());
  integrator.Add(Tracked(Eigen::Isometry3d::Identity(), nullptr));  // the first frame
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  for (int i = 0; i < 2000; ++i) {
    T_world_camera = Track(&integrator, T_world_camera, 1);
    ASSERT_TRUE(integrator.T_map_odom().matrix() == Eigen::Matrix4d::Identity()) << i;
    ASSERT_TRUE(integrator.T_odom_camera().matrix() == T_world_camera.matrix()) << i;
  }
  EXPECT_TRUE(integrator.has_pose());
}

TEST(OdomIntegrator, CorrectionBetweenFramesGoesIntoMapOdom) {
  OdomIntegrator integrator;
  integrator.Add(Tracked(Eigen::Isometry3d::Identity(), nullptr));
  const Eigen::Isometry3d last = Track(&integrator, Eigen::Isometry3d::Identity(), 10);
  const Eigen::Isometry3d T_odom_last = integrator.T_odom_camera();
  // The back end moves the last pose; the next frame is tracked on from the corrected pose.
  const Eigen::Isometry3d corrected = Correction() * last;
  const Eigen::Isometry3d next = corrected * Step();
  integrator.Add(Tracked(next, &corrected));
  // Odom moved by the tracked step only: continuous.
  EXPECT_TRUE(Near(integrator.T_odom_camera(), T_odom_last * Step()));
  // map -> odom holds the correction, and the two still give the tracker's pose.
  EXPECT_TRUE(Near(integrator.T_map_odom(), Correction()));
  EXPECT_TRUE(Near(integrator.T_map_odom() * integrator.T_odom_camera(), next));
  // Then it stays as it is until the next correction, whatever the motion.
  const Eigen::Isometry3d T_map_odom = integrator.T_map_odom();
  const Eigen::Isometry3d later = Track(&integrator, next, 50);
  EXPECT_TRUE(integrator.T_map_odom().matrix() == T_map_odom.matrix());
  EXPECT_TRUE(Near(integrator.T_map_odom() * integrator.T_odom_camera(), later));
}

TEST(OdomIntegrator, CorrectionsAccumulateInMapOdom) {
  OdomIntegrator integrator;
  integrator.Add(Tracked(Eigen::Isometry3d::Identity(), nullptr));
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_odom_expected = Eigen::Isometry3d::Identity();
  for (int k = 0; k < 3; ++k) {
    T_world_camera = Track(&integrator, T_world_camera, 5);
    for (int i = 0; i < 5; ++i) T_odom_expected = T_odom_expected * Step();
    const Eigen::Isometry3d corrected = Correction() * T_world_camera;
    T_world_camera = corrected * Step();
    T_odom_expected = T_odom_expected * Step();
    integrator.Add(Tracked(T_world_camera, &corrected));
  }
  EXPECT_TRUE(Near(integrator.T_odom_camera(), T_odom_expected));
  EXPECT_TRUE(Near(integrator.T_map_odom() * integrator.T_odom_camera(), T_world_camera));
  EXPECT_FALSE(Near(integrator.T_map_odom(), Eigen::Isometry3d::Identity()));
}

TEST(OdomIntegrator, RelocalisationJumpGoesIntoMapOdomAndOdomStays) {
  OdomIntegrator integrator;
  integrator.Add(Tracked(Eigen::Isometry3d::Identity(), nullptr));
  const Eigen::Isometry3d last = Track(&integrator, Eigen::Isometry3d::Identity(), 10);
  const Eigen::Isometry3d T_odom_last = integrator.T_odom_camera();
  integrator.Add(Lost());
  integrator.Add(Lost());
  EXPECT_TRUE(integrator.T_odom_camera().matrix() == T_odom_last.matrix());
  // Relocalised 0.5 m and 20 deg away: reported without a previous pose.
  const Eigen::Isometry3d jumped = last * Eigen::Translation3d(0.5, 0.0, 0.1) *
                                   Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitY());
  integrator.Add(Tracked(jumped, nullptr));
  EXPECT_TRUE(integrator.T_odom_camera().matrix() == T_odom_last.matrix());
  EXPECT_TRUE(Near(integrator.T_map_odom() * integrator.T_odom_camera(), jumped));
  // Tracking goes on: odom moves by the steps from where it stayed.
  const Eigen::Isometry3d after = Track(&integrator, jumped, 3);
  EXPECT_TRUE(Near(integrator.T_odom_camera(), T_odom_last * Step() * Step() * Step()));
  EXPECT_TRUE(Near(integrator.T_map_odom() * integrator.T_odom_camera(), after));
}

// The reset service (ResetMode::kKeepPose): the re-initialised frame reports no pose, the next is
// tracked on from the re-initialised pose (the last one): both odom and map -> odom are kept.
TEST(OdomIntegrator, ResetKeepingThePoseKeepsOdomAndMapOdom) {
  OdomIntegrator integrator;
  integrator.Add(Tracked(Eigen::Isometry3d::Identity(), nullptr));
  Eigen::Isometry3d last = Track(&integrator, Eigen::Isometry3d::Identity(), 5);
  const Eigen::Isometry3d corrected = Correction() * last;  // a map -> odom to keep
  last = corrected * Step();
  integrator.Add(Tracked(last, &corrected));
  const Eigen::Isometry3d T_map_odom = integrator.T_map_odom();
  const Eigen::Isometry3d T_odom_last = integrator.T_odom_camera();
  FrameResult reinitialised;  // at the last pose, not reported
  reinitialised.state = TrackingState::kInitialised;
  reinitialised.reset = true;
  integrator.Add(reinitialised);
  const Eigen::Isometry3d next = last * Step();
  integrator.Add(Tracked(next, &last));
  EXPECT_TRUE(integrator.T_map_odom().matrix() == T_map_odom.matrix());
  EXPECT_TRUE(Near(integrator.T_odom_camera(), T_odom_last * Step()));
}

// Time going backwards: the tracker starts a new world at the origin; the node restarts odom.
TEST(OdomIntegrator, RestartStartsOdomAndMapOdomAtIdentity) {
  OdomIntegrator integrator;
  integrator.Add(Tracked(Eigen::Isometry3d::Identity(), nullptr));
  const Eigen::Isometry3d last = Track(&integrator, Eigen::Isometry3d::Identity(), 5);
  const Eigen::Isometry3d corrected = Correction() * last;
  integrator.Add(Tracked(corrected * Step(), &corrected));
  ASSERT_FALSE(Near(integrator.T_map_odom(), Eigen::Isometry3d::Identity()));
  integrator.Restart();
  EXPECT_FALSE(integrator.has_pose());
  integrator.Add(Tracked(Eigen::Isometry3d::Identity(), nullptr));  // the new world's first
  EXPECT_TRUE(integrator.T_map_odom().matrix() == Eigen::Matrix4d::Identity());
  EXPECT_TRUE(integrator.T_odom_camera().matrix() == Eigen::Matrix4d::Identity());
  const Eigen::Isometry3d later = Track(&integrator, Eigen::Isometry3d::Identity(), 5);
  EXPECT_TRUE(integrator.T_map_odom().matrix() == Eigen::Matrix4d::Identity());
  EXPECT_TRUE(integrator.T_odom_camera().matrix() == later.matrix());
}

}  // namespace
}  // namespace dslam
