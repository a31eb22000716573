// Loop files (dslam/io/loop_io.h): written and read back exactly to the printed digits; malformed
// lines are refused with the file and line.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>

#include "dslam/io/loop_io.h"

namespace dslam {
namespace {

TEST(LoopIo, WritesAndReadsBack) {
  LoopRecord loop;
  loop.stamp_query_s = 1030.5;
  loop.stamp_match_s = 1000.25;
  loop.T_match_query.linear() =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  loop.T_match_query.translation() = Eigen::Vector3d(0.1, -0.02, 0.345678);
  const std::string path = testing::TempDir() + "/loops.txt";
  WriteLoopFile(path, {loop, loop});
  const std::vector<LoopRecord> read = ReadLoopFile(path);
  ASSERT_EQ(read.size(), 2u);
  EXPECT_DOUBLE_EQ(read[0].stamp_query_s, 1030.5);
  EXPECT_DOUBLE_EQ(read[0].stamp_match_s, 1000.25);
  EXPECT_LT((read[0].T_match_query.matrix() - loop.T_match_query.matrix()).cwiseAbs().maxCoeff(),
            1e-6);
  std::remove(path.c_str());
}

TEST(LoopIo, SkipsCommentsAndNormalisesQuaternions) {
  std::istringstream in("# header\n\n1 2 0 0 0 0 0 0 2\n");
  const std::vector<LoopRecord> loops = ParseLoopFile(in, "x.txt");
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_TRUE(loops[0].T_match_query.isApprox(Eigen::Isometry3d::Identity()));
}

TEST(LoopIo, RefusesMalformedLinesWithTheirPlace) {
  std::istringstream short_line("1 2 0 0 0 0 0 1\n");
  try {
    ParseLoopFile(short_line, "loops.txt");
    FAIL() << "a line of 8 numbers was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("loops.txt:1"), std::string::npos) << e.what();
  }
  std::istringstream zero("# c\n1 2 0 0 0 0 0 0 0\n");
  EXPECT_THROW(ParseLoopFile(zero, "loops.txt"), std::runtime_error);
  EXPECT_THROW(ReadLoopFile("/nonexistent/loops.txt"), std::runtime_error);
}

}  // namespace
}  // namespace dslam
