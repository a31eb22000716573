// HeapReport under the allocator the test binary was linked with: test_ros with glibc's malloc,
// test_heap_report_jemalloc with jemalloc linked first (as dslam_odometry_node is).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "dslam/ros/heap_report.h"

namespace dslam {
namespace ros_layer {
namespace {

/// The first number of the report [MB]: allocated (jemalloc) or in use (glibc).
double FirstMb(const std::string& report) {
  const size_t colon = report.find(": ");
  double mb = -1.0;
  if (colon != std::string::npos) std::sscanf(report.c_str() + colon + 2, "%lf MB", &mb);
  return mb;
}

/// A live 64 MB block (touched, so every page is resident) raises the first number by 64 MB.
void ExpectBlockCounted(const std::string& prefix) {
  const std::string before = HeapReport();
  ASSERT_EQ(before.rfind(prefix, 0), 0u) << before;
  constexpr size_t kBytes = size_t{64} << 20;
  std::unique_ptr<char[]> block(new char[kBytes]);
  std::memset(block.get(), 1, kBytes);
  const std::string during = HeapReport();
  block.reset();
  EXPECT_NEAR(FirstMb(during) - FirstMb(before), 64.0, 2.0) << before << " / " << during;
}

#ifdef DSLAM_TEST_JEMALLOC
TEST(HeapReport, JemallocLinkedFirstServesMallocAndReportsIt) {
  EXPECT_EQ(CurrentAllocator(), Allocator::kJemalloc);
  ExpectBlockCounted("heap (jemalloc): ");
  ReleaseFreeHeapMemory();  // nothing to do under jemalloc; must not fail
}
#else
TEST(HeapReport, GlibcMallocReportsItsArenas) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "the sanitizer's malloc serves this build, not glibc's";
#endif
  EXPECT_EQ(CurrentAllocator(), Allocator::kGlibc);
  ExpectBlockCounted("heap (glibc): ");
  ReleaseFreeHeapMemory();
}
#endif

}  // namespace
}  // namespace ros_layer
}  // namespace dslam
