// KeyFrameMotion: the motion of a keyframe a correction moved, and the nearest-older rule for the
// others.
#include <gtest/gtest.h>

#include "dslam/core/keyframe_motion.h"

namespace dslam {
namespace {

Eigen::Isometry3d Shift(double x) {
  return Eigen::Isometry3d(Eigen::Translation3d(x, 0.0, 0.0));
}

double ShiftOf(const KeyFrameMotion& motion, int id) {
  return motion.For(id).translation().x();
}

TEST(KeyFrameMotion, UnknownKeyFramesMoveWithTheNearestOlderOrElseTheNearestNewer) {
  KeyFrameMotion motion;
  EXPECT_TRUE(motion.empty());
  EXPECT_TRUE(motion.For(3).isApprox(Eigen::Isometry3d::Identity()));
  // Keyframe 2 moved from x = 5 to x = 6, keyframe 5 from x = 1 to x = 4: T_new_old shifts by 1, 3.
  motion.Add(2, Shift(6.0), Shift(5.0));
  motion.Add(5, Shift(4.0), Shift(1.0));
  EXPECT_FALSE(motion.empty());
  EXPECT_DOUBLE_EQ(ShiftOf(motion, 0), 1.0);  // none older: the nearest newer (2)
  EXPECT_DOUBLE_EQ(ShiftOf(motion, 2), 1.0);  // itself
  EXPECT_DOUBLE_EQ(ShiftOf(motion, 4), 1.0);  // the nearest older (2)
  EXPECT_DOUBLE_EQ(ShiftOf(motion, 5), 3.0);
  EXPECT_DOUBLE_EQ(ShiftOf(motion, 90), 3.0);
}

TEST(KeyFrameMotion, TheMotionMapsTheOldPoseOntoTheNew) {
  const Eigen::Isometry3d T_old = Eigen::Translation3d(1.0, 2.0, 3.0) *
                                  Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ());
  const Eigen::Isometry3d T_new = Eigen::Translation3d(-1.0, 0.5, 3.2) *
                                  Eigen::AngleAxisd(-0.3, Eigen::Vector3d(1, 1, 0).normalized());
  KeyFrameMotion motion;
  motion.Add(7, T_new, T_old);
  EXPECT_TRUE((motion.For(7) * T_old).isApprox(T_new, 1e-12));
}

}  // namespace
}  // namespace dslam
