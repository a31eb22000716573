// StaticMapper fed by Slam on a rendered sequence: the threaded mode (fusion on the back-end
// thread, the map read concurrently as the ROS timer and service do) gives the synchronous mode's
// map, and Slam's resets reach the map. Also run under ThreadSanitizer by scripts/sanitize.sh.
#include <algorithm>
#include <array>
#include <atomic>
#include <memory>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/backend/slam.h"
#include "dslam/mapping/static_mapper.h"
#include "support/rendered_sequence.h"

namespace dslam {
namespace {

constexpr int kFrames = 40;

// Frames [begin, end) of the first kFrames of `walking` (rendered once) through `slam`.
void Feed(Slam* slam, int begin, int end) {
  const test::RenderedSequence& walking = test::SharedSequence("walking", kFrames);
  for (int i = begin; i < end; ++i) slam->ProcessFrame(walking.frames[i], FrameRequest{});
}

// Sorted coordinates of a cloud, for comparing two maps whatever their order.
std::vector<std::array<float, 3>> Sorted(const ColouredCloud& cloud) {
  std::vector<std::array<float, 3>> points;
  for (const ColouredPoint& p : cloud) points.push_back({p.p.x(), p.p.y(), p.p.z()});
  std::sort(points.begin(), points.end());
  return points;
}

TEST(StaticMapSlam, ThreadedFusionGivesTheSynchronousMapWhileItIsRead) {
  // The back end off: both modes track alike and make the same keyframes.
  auto sync_map = std::make_shared<StaticMapper>(Config());
  {
    Slam slam(Config(), BackEndMode::kSynchronous, RefinedPoseRecording::kOff, {sync_map});
    Feed(&slam, 0, kFrames);
  }
  auto threaded_map = std::make_shared<StaticMapper>(Config());
  std::atomic<bool> done{false};
  size_t reads = 0;
  std::thread reader([&] {  // as the node's timer and save_map service
    while (!done) {
      reads += threaded_map->Cloud().size() > 0;
      threaded_map->stats();
      threaded_map->revision();
    }
  });
  {
    Slam slam(Config(), BackEndMode::kThreaded, RefinedPoseRecording::kOff, {threaded_map});
    Feed(&slam, 0, kFrames);
    slam.WaitForBackEnd();
  }
  done = true;
  reader.join();
  EXPECT_GT(reads, 0u);
  const StaticMapStats sync = sync_map->stats(), threaded = threaded_map->stats();
  EXPECT_GE(sync.window_keyframes + sync.fused_keyframes, 4);
  EXPECT_EQ(threaded.fused_keyframes, sync.fused_keyframes);
  EXPECT_EQ(threaded.window_keyframes, sync.window_keyframes);
  EXPECT_EQ(threaded.transient_points, sync.transient_points);
  EXPECT_EQ(Sorted(threaded_map->Cloud()), Sorted(sync_map->Cloud()));
}

TEST(StaticMapSlam, ResetsReachTheMap) {
  for (const BackEndMode mode : {BackEndMode::kSynchronous, BackEndMode::kThreaded}) {
    Config config;
    config.backend.enabled = true;
    auto map = std::make_shared<StaticMapper>(config);
    Slam slam(config, mode, RefinedPoseRecording::kOff, {map});
    Feed(&slam, 0, 20);
    slam.WaitForBackEnd();
    ASSERT_GT(map->stats().window_keyframes, 0);
    const size_t before = map->Cloud().size();
    slam.Reset(ResetMode::kKeepPose);  // the world frame goes on: the window is fused for good
    slam.WaitForBackEnd();
    EXPECT_EQ(map->stats().window_keyframes, 0);
    EXPECT_GT(map->stats().voxels, 0u);
    EXPECT_LE(map->Cloud().size(), before);  // the free-space check may drop some
    Feed(&slam, 20, 30);
    slam.Reset(ResetMode::kNewWorld);
    slam.WaitForBackEnd();
    EXPECT_TRUE(map->Cloud().empty());
    EXPECT_EQ(map->stats().fused_keyframes, 0);
    Feed(&slam, 30, kFrames);
    slam.WaitForBackEnd();
    EXPECT_FALSE(map->Cloud().empty());  // the new world's keyframes
  }
}

}  // namespace
}  // namespace dslam
