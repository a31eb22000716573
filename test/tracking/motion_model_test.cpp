#include <gtest/gtest.h>

#include "dslam/tracking/motion_model.h"

namespace dslam {
namespace {

Eigen::Isometry3d Pose(double yaw, const Eigen::Vector3d& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).matrix();
  T.translation() = t;
  return T;
}

TEST(ConstantVelocityModel, ExtrapolatesUniformMotion) {
  ConstantVelocityModel model;
  EXPECT_FALSE(model.has_pose());
  model.Update(0.0, Pose(0.0, {0, 0, 0}));
  EXPECT_TRUE(model.Predict(0.1, 1.0).isApprox(Pose(0.0, {0, 0, 0})));  // no velocity yet
  model.Update(0.1, Pose(0.02, {0.01, 0, 0.03}));
  // Constant twist in the camera frame: two equal steps compose.
  const Eigen::Isometry3d step = Pose(0.0, {0, 0, 0}).inverse() * Pose(0.02, {0.01, 0, 0.03});
  EXPECT_TRUE(model.Predict(0.2, 1.0).isApprox(Pose(0.02, {0.01, 0, 0.03}) * step, 1e-9));
  // Half the time: half the rotation angle.
  const Eigen::AngleAxisd half(model.last_pose().inverse().rotation() *
                               model.Predict(0.15, 1.0).rotation());
  EXPECT_NEAR(half.angle(), 0.01, 1e-9);
}

TEST(ConstantVelocityModel, ForgetVelocityKeepsLastPose) {
  ConstantVelocityModel model;
  model.Update(0.0, Pose(0.0, {0, 0, 0}));
  model.Update(0.1, Pose(0.0, {0.1, 0, 0}));
  model.ForgetVelocity();
  EXPECT_TRUE(model.Predict(0.2, 1.0).isApprox(Pose(0.0, {0.1, 0, 0})));
  model.Reset();
  EXPECT_FALSE(model.has_pose());
  EXPECT_TRUE(model.last_pose().isApprox(Eigen::Isometry3d::Identity()));
}

TEST(ConstantVelocityModel, NoExtrapolationOverALongGap) {
  ConstantVelocityModel model;
  model.Update(0.0, Pose(0.0, {0, 0, 0}));
  model.Update(0.1, Pose(0.0, {0.1, 0, 0}));  // 1 m/s along x
  EXPECT_FALSE(model.IsGap(1.1, 1.0));
  EXPECT_TRUE(model.Predict(1.1, 1.0).isApprox(Pose(0.0, {1.1, 0, 0}), 1e-9));
  EXPECT_TRUE(model.IsGap(1.2, 1.0));  // 1.1 s since the last pose: the velocity is stale
  EXPECT_TRUE(model.Predict(1.2, 1.0).isApprox(Pose(0.0, {0.1, 0, 0})));
  EXPECT_TRUE(model.Predict(60.0, 1.0).isApprox(Pose(0.0, {0.1, 0, 0})));
  EXPECT_FALSE(ConstantVelocityModel().IsGap(100.0, 1.0));  // no pose: nothing to be stale
}

}  // namespace
}  // namespace dslam
