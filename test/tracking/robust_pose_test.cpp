#include "dslam/tracking/robust_pose.h"

#include <gtest/gtest.h>

#include "support/textured_frame.h"
#include "tracking/pose_scene.h"

namespace dslam {
namespace {

TEST(RobustPose, RansacFindsPoseWithSixtyPercentOutliers) {
  const PinholeCamera camera = test::TestCamera();
  const test::PoseScene scene = test::MakePoseScene(camera, 200, 0.6, 21);
  const RansacResult ransac = RansacPose(scene.observations, PoseConfig(), 5);
  ASSERT_TRUE(ransac.success);
  EXPECT_LT((ransac.T_camera_world.translation() - scene.T_camera_world.translation()).norm(),
            0.02);
  EXPECT_LT(test::RotationErrorDeg(ransac.T_camera_world, scene.T_camera_world), 1.0);
  EXPECT_LE(ransac.hypotheses, kRansacMaxHypotheses);

  const PoseResult refined = EstimatePoseRobust(scene.observations, camera, PoseConfig(), 5);
  ASSERT_TRUE(refined.success);
  EXPECT_LT((refined.T_camera_world.translation() - scene.T_camera_world.translation()).norm(),
            0.005);
  EXPECT_LT(test::RotationErrorDeg(refined.T_camera_world, scene.T_camera_world), 0.2);
  for (size_t i = 0; i < scene.observations.size(); ++i) {
    if (scene.is_outlier[i]) {
      EXPECT_FALSE(refined.inliers[i]) << i;
    }
  }
}

TEST(RobustPose, AdaptiveStoppingOnCleanData) {
  const PinholeCamera camera = test::TestCamera();
  const test::PoseScene scene = test::MakePoseScene(camera, 100, 0.0, 22);
  const RansacResult ransac = RansacPose(scene.observations, PoseConfig(), 6);
  ASSERT_TRUE(ransac.success);
  EXPECT_LT(ransac.hypotheses, 30);  // w ~ 1: a handful of hypotheses suffice
  EXPECT_GT(ransac.num_inliers, 90);
}

TEST(RobustPose, FailsWithoutDepth) {
  const PinholeCamera camera = test::TestCamera();
  const test::PoseScene scene = test::MakePoseScene(camera, 50, 0.0, 23, 1);  // all pixel-only
  EXPECT_FALSE(RansacPose(scene.observations, PoseConfig()).success);
  EXPECT_FALSE(EstimatePoseRobust(scene.observations, camera, PoseConfig()).success);
}

}  // namespace
}  // namespace dslam
