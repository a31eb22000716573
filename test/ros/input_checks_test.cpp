#include "dslam/ros/input_checks.h"

#include <gtest/gtest.h>

namespace dslam {
namespace ros_layer {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(StampCheck, NormalStampsPassSilently) {
  StampCheck check(1.0);
  for (int i = 0; i < 5; ++i) {
    const StampVerdict v = check.Check(100.0 + i / 30.0);
    EXPECT_TRUE(v.accept);
    EXPECT_TRUE(v.problem.empty());
    EXPECT_FALSE(v.backwards);
  }
}

TEST(StampCheck, ZeroAndRepeatedStampsAreSkipped) {
  StampCheck check(1.0);
  EXPECT_FALSE(check.Check(0.0).accept);
  EXPECT_TRUE(Contains(check.Check(0.0).problem, "zero timestamp"));
  EXPECT_TRUE(check.Check(5.0).accept);
  const StampVerdict repeated = check.Check(5.0);
  EXPECT_FALSE(repeated.accept);
  EXPECT_TRUE(Contains(repeated.problem, "repeated timestamp 5.000000"));
  EXPECT_TRUE(check.Check(5.1).accept);  // the skipped ones did not move the reference
}

TEST(StampCheck, BackwardsAndGapsAreAcceptedWithANote) {
  StampCheck check(1.0);
  check.Check(10.0);
  const StampVerdict gap = check.Check(12.5);
  EXPECT_TRUE(gap.accept);
  EXPECT_FALSE(gap.backwards);
  EXPECT_TRUE(Contains(gap.problem, "2.500 s since the previous frame"));
  const StampVerdict back = check.Check(3.0);
  EXPECT_TRUE(back.accept);
  EXPECT_TRUE(back.backwards);
  EXPECT_TRUE(Contains(back.problem, "time went backwards by 9.500 s"));
  EXPECT_TRUE(check.Check(3.03).problem.empty());  // the new run goes on from 3.0
}

TEST(InputWatchdog, NamesTheMissingInput) {
  InputWatchdog watchdog({"/cam/rgb", "/cam/depth", "/cam/info"});
  EXPECT_EQ(watchdog.Check(), "");  // nothing arrived at all: nothing to say
  watchdog.Arrived(InputWatchdog::kColour, 1.0);
  watchdog.Arrived(InputWatchdog::kDepth, 1.0);
  const std::string warning = watchdog.Check();
  EXPECT_TRUE(Contains(warning, "nothing on /cam/info")) << warning;
  EXPECT_FALSE(Contains(warning, "/cam/rgb")) << warning;
  EXPECT_EQ(watchdog.Check(), "");  // the counts are per period
}

TEST(InputWatchdog, StampsThatNeverMatchAndSilenceWhenSynchronized) {
  InputWatchdog watchdog({"a", "b", "c"});
  watchdog.Arrived(InputWatchdog::kColour, 1.0);
  watchdog.Arrived(InputWatchdog::kDepth, 7.5);
  watchdog.Arrived(InputWatchdog::kInfo, 1.0);
  const std::string warning = watchdog.Check();
  EXPECT_TRUE(Contains(warning, "never match")) << warning;
  EXPECT_TRUE(Contains(warning, "depth 7.500000")) << warning;
  watchdog.Arrived(InputWatchdog::kColour, 2.0);
  watchdog.Synchronized();
  EXPECT_EQ(watchdog.Check(), "");
}

}  // namespace
}  // namespace ros_layer
}  // namespace dslam
