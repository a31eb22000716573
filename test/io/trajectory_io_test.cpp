#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "dslam/io/trajectory_io.h"

namespace dslam {
namespace {

TEST(TrajectoryIo, WriteReadRoundTrip) {
  Trajectory trajectory;
  for (int i = 0; i < 5; ++i) {
    StampedPose pose;
    pose.stamp_s = 1548339829.93029 + i / 30.0;
    pose.T_world_camera.linear() =
        Eigen::AngleAxisd(0.1 * i, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    pose.T_world_camera.translation() = Eigen::Vector3d(0.5 * i, -1.0, 2.0 + i);
    trajectory.push_back(pose);
  }
  const std::string path = testing::TempDir() + "/dslam_traj.txt";
  WriteTumTrajectory(path, trajectory);
  const Trajectory read = ReadTumTrajectory(path);
  ASSERT_EQ(read.size(), trajectory.size());
  for (size_t i = 0; i < read.size(); ++i) {
    EXPECT_NEAR(read[i].stamp_s, trajectory[i].stamp_s, 1e-6);
    EXPECT_TRUE(read[i].T_world_camera.isApprox(trajectory[i].T_world_camera, 1e-6));
  }
}

TEST(TrajectoryIo, SortsNormalisesAndRejectsBadLines) {
  const std::string path = testing::TempDir() + "/dslam_traj_bad.txt";
  {
    std::ofstream out(path);
    out << "# comment\n2.0 1 2 3 0 0 0 2\n1.0 0 0 0 0 0 0 1\n";
  }
  const Trajectory read = ReadTumTrajectory(path);
  ASSERT_EQ(read.size(), 2u);
  EXPECT_DOUBLE_EQ(read[0].stamp_s, 1.0);
  EXPECT_TRUE(read[1].T_world_camera.linear().isApprox(Eigen::Matrix3d::Identity()));
  {
    std::ofstream out(path);
    out << "1.0 0 0 0 0 0 1\n";
  }
  EXPECT_THROW(ReadTumTrajectory(path), std::runtime_error);
  EXPECT_THROW(ReadTumTrajectory(path + ".missing"), std::runtime_error);
}

TEST(TrajectoryIo, HugeQuaternionCoefficientsKeepTheirRotation) {
  // (qx, qw) = (1e200, 1): 180 degrees about x; the norm overflowed and read as the identity.
  std::istringstream in("0 0 0 0 1e200 0 0 1\n");
  const Trajectory read = ParseTumTrajectory(in, "huge.txt");
  ASSERT_EQ(read.size(), 1u);
  EXPECT_TRUE(read[0].T_world_camera.linear().isApprox(
      Eigen::Vector3d(1, -1, -1).asDiagonal().toDenseMatrix(), 1e-12));
  std::istringstream bad("1.0 0 0 0 0 0 x 1\n");
  try {
    ParseTumTrajectory(bad, "bad.txt");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.txt:1:"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dslam
