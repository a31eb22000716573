// Slam with the back end on its own thread (BackEndMode::kThreaded) against the synchronous mode
// on one short rendered sequence, and the back-end queue: backlog, coalescing, hold, Reset and
// destruction with keyframes queued, and a dynamic scene whose map changes while a run is in
// flight. Also run under ThreadSanitizer by CI (scripts/test.sh) and scripts/sanitize.sh.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <thread>

#include <gtest/gtest.h>

#include "dslam/backend/slam.h"
#include "support/ate.h"
#include "support/rendered_sequence.h"
#include "support/slam_test_access.h"

namespace dslam {
namespace {

// The sequence of every test of this file but the last: test::SharedSequence(kScene, kFrames).
constexpr char kScene[] = "static_room";
constexpr int kFrames = 45;

// The back end on; one keyframe held fixed, so that local BA runs from the second keyframe on.
Config BackEndOn() {
  Config config;
  config.backend.enabled = true;
  config.backend.ba_fixed_keyframes = 1;
  return config;
}

struct RunResult {
  double ate_m = 0.0, refined_ate_m = 0.0;
  int with_pose = 0, keyframes = 0, runs = 0, delivered = 0, max_backlog = 0;
};

// Feeds every frame, `gap` apart (a camera's frame interval), then collects the runs left over.
RunResult RunSequence(BackEndMode mode, std::chrono::milliseconds gap) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  Slam slam(BackEndOn(), mode);
  RunResult out;
  const Trajectory estimated =
      test::TrackAll(&slam, room.frames, [&](size_t, const FrameResult& r) {
        out.with_pose += r.has_pose;
        out.keyframes += r.keyframe;
        out.runs += r.backend.ba.ran;
        out.delivered += r.backend_thread.delivered;
        out.max_backlog = std::max(out.max_backlog, r.backend_thread.backlog);
        std::this_thread::sleep_for(gap);
      });
  slam.WaitForBackEnd();
  for (const BackEndStatus& run : slam.TakeUnreportedRuns()) out.runs += run.ba.ran;
  out.ate_m = test::AteRmse(estimated, room.groundtruth);
  out.refined_ate_m = test::AteRmse(slam.RefinedPoses(), room.groundtruth);
  return out;
}

TEST(SlamThreads, ThreadedTracksLikeSynchronous) {
  const RunResult sync = RunSequence(BackEndMode::kSynchronous, std::chrono::milliseconds(0));
  EXPECT_EQ(sync.with_pose, kFrames);
  EXPECT_GE(sync.runs, 4);  // measured: 6 keyframes, local BA ran after 4 (from the third)
  EXPECT_EQ(sync.delivered, 0);
  EXPECT_EQ(sync.max_backlog, 0);
  // A camera's gap between frames lets the back end run before the next frame; none: the
  // tracking thread may take the lock first and keyframes coalesce. Both must stay as accurate.
  for (const int gap_ms : {5, 0}) {
    const RunResult threaded =
        RunSequence(BackEndMode::kThreaded, std::chrono::milliseconds(gap_ms));
    EXPECT_EQ(threaded.with_pose, kFrames) << "gap " << gap_ms << " ms";
    // Without a gap, how many keyframes coalesce depends on the scheduler: at least one run.
    EXPECT_GE(threaded.runs, gap_ms > 0 ? 2 : 1) << "gap " << gap_ms << " ms";
    EXPECT_LE(threaded.runs, threaded.keyframes) << "gap " << gap_ms << " ms";
    EXPECT_GE(threaded.max_backlog, 1) << "gap " << gap_ms << " ms";
    // Measured: 1.69-1.74 mm against 1.74 mm synchronous (the back end changes it by ~3%).
    EXPECT_LT(threaded.ate_m, 1.1 * sync.ate_m + 0.0002) << "gap " << gap_ms << " ms";
    EXPECT_LT(threaded.refined_ate_m, 1.1 * sync.refined_ate_m + 0.0002) << "gap " << gap_ms;
  }
}

// Feeds frames from `*next_frame` on until `keyframes` keyframes were made; returns the last
// result.
FrameResult FeedKeyFrames(Slam* slam, int keyframes, int* next_frame) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  FrameResult r;
  for (int made = 0; made < keyframes && *next_frame < kFrames; ++*next_frame) {
    r = slam->ProcessFrame(room.frames[*next_frame]);
    made += r.keyframe;
  }
  return r;
}

TEST(SlamThreads, HeldBackEndQueuesKeyFramesAndCoalescesThem) {
  Slam slam(BackEndOn(), BackEndMode::kThreaded);
  SlamTestAccess::HoldBackEnd(&slam, true);
  int next = 0;
  for (int queued = 1; queued <= 4; ++queued) {
    const FrameResult r = FeedKeyFrames(&slam, 1, &next);
    ASSERT_TRUE(r.keyframe);
    EXPECT_TRUE(r.backend_thread.threaded);
    EXPECT_EQ(r.backend_thread.backlog, queued);
    EXPECT_FALSE(r.backend_thread.delivered);
  }
  slam.WaitForBackEnd();  // releases the hold
  const std::vector<BackEndStatus> runs = slam.TakeUnreportedRuns();
  ASSERT_EQ(runs.size(), 1u);  // four keyframes, one run for the newest window
  EXPECT_TRUE(runs[0].ba.ran);
  EXPECT_EQ(runs[0].window_keyframes, 4);
  EXPECT_TRUE(slam.TakeUnreportedRuns().empty());  // each run is reported once
  const FrameResult after = slam.ProcessFrame(test::SharedSequence(kScene, kFrames).frames[next]);
  EXPECT_EQ(after.backend_thread.backlog, after.keyframe ? 1 : 0);
  EXPECT_FALSE(after.backend_thread.delivered);
}

TEST(SlamThreads, CompletedRunIsReportedByTheNextFrame) {
  Slam slam(BackEndOn(), BackEndMode::kThreaded);
  SlamTestAccess::HoldBackEnd(&slam, true);
  int next = 0;
  FeedKeyFrames(&slam, 3, &next);
  slam.WaitForBackEnd();  // releases the hold: one run over the window of three, completed
  const FrameResult r = slam.ProcessFrame(test::SharedSequence(kScene, kFrames).frames[next]);
  EXPECT_TRUE(r.backend_thread.delivered);
  EXPECT_TRUE(r.backend.ba.ran);
  EXPECT_EQ(r.backend.window_keyframes, 3);
  slam.WaitForBackEnd();
  for (const BackEndStatus& run : slam.TakeUnreportedRuns()) {
    EXPECT_EQ(run.window_keyframes, 4);  // only the run after this frame, when a keyframe
  }
}

TEST(SlamThreads, ResetDropsQueuedKeyFrames) {
  Slam slam(BackEndOn(), BackEndMode::kThreaded);
  SlamTestAccess::HoldBackEnd(&slam, true);
  int next = 0;
  EXPECT_EQ(FeedKeyFrames(&slam, 3, &next).backend_thread.backlog, 3);
  slam.Reset(ResetMode::kNewWorld);
  slam.WaitForBackEnd();
  EXPECT_TRUE(slam.TakeUnreportedRuns().empty());  // nothing ran: the queue was dropped
  const FrameResult first = slam.ProcessFrame(test::SharedSequence(kScene, kFrames).frames[next]);
  EXPECT_EQ(first.state, TrackingState::kInitialised);
  EXPECT_EQ(first.frame_index, 0);
  EXPECT_EQ(first.backend_thread.backlog, 1);  // the new map's first keyframe
  EXPECT_FALSE(first.backend_thread.delivered);
  EXPECT_EQ(slam.MapSnapshot().window().size(), 1u);
}

TEST(SlamThreads, ResetRightAfterKeyFramesNeverReportsOldRuns) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  Slam slam(BackEndOn(), BackEndMode::kThreaded);
  int next = 0;
  for (int round = 0; round < 3; ++round) {
    FeedKeyFrames(&slam, 2, &next);  // the back end may be running, queued or done
    slam.Reset(ResetMode::kNewWorld);
    const FrameResult first = slam.ProcessFrame(room.frames[next++]);
    EXPECT_EQ(first.state, TrackingState::kInitialised) << "round " << round;
    EXPECT_FALSE(first.backend_thread.delivered) << "round " << round;
  }
  slam.WaitForBackEnd();
  // Only the run on the last map's first keyframe: earlier rounds' runs went with their resets.
  const std::vector<BackEndStatus> runs = slam.TakeUnreportedRuns();
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].window_keyframes, 1);
  EXPECT_FALSE(runs[0].ba.ran);  // 1 keyframe
}

// Destroys `slam` on another thread; fails (and leaks the thread) when that takes over 60 s.
void ExpectPromptDestruction(std::unique_ptr<Slam> slam) {
  std::packaged_task<void()> destroy([s = std::move(slam)]() mutable { s.reset(); });
  std::future<void> done = destroy.get_future();
  std::thread destroyer(std::move(destroy));
  if (done.wait_for(std::chrono::seconds(60)) == std::future_status::ready) {
    destroyer.join();
  } else {
    ADD_FAILURE() << "~Slam did not return (deadlock?)";
    destroyer.detach();
  }
}

TEST(SlamThreads, DestructionWithKeyFramesQueued) {
  auto held = std::make_unique<Slam>(BackEndOn(), BackEndMode::kThreaded);
  SlamTestAccess::HoldBackEnd(held.get(), true);
  int next = 0;
  EXPECT_EQ(FeedKeyFrames(held.get(), 3, &next).backend_thread.backlog, 3);
  ExpectPromptDestruction(std::move(held));

  auto released = std::make_unique<Slam>(BackEndOn(), BackEndMode::kThreaded);
  SlamTestAccess::HoldBackEnd(released.get(), true);
  next = 0;
  FeedKeyFrames(released.get(), 3, &next);
  // The run starts (or is about to) while the destructor runs.
  SlamTestAccess::HoldBackEnd(released.get(), false);
  ExpectPromptDestruction(std::move(released));
}

TEST(SlamThreads, SynchronousModeReportsEachRunWithItsKeyFrame) {
  Slam slam(BackEndOn(), BackEndMode::kSynchronous);
  SlamTestAccess::HoldBackEnd(&slam, true);  // no effect
  int next = 0;
  const FrameResult r = FeedKeyFrames(&slam, 3, &next);
  EXPECT_TRUE(r.backend.ba.ran);  // a window of three: static points seen in two or more
  EXPECT_FALSE(r.backend_thread.threaded);
  EXPECT_EQ(r.backend_thread.backlog, 0);
  slam.WaitForBackEnd();
  EXPECT_TRUE(slam.TakeUnreportedRuns().empty());
}

// Points of `before`'s window keyframes that are still in `after` and that tracking changed in
// between (matched again, moved, or relabelled).
int ChangedPoints(const Map& before, const Map& after) {
  int changed = 0;
  for (const KeyFrame& keyframe : before.window()) {
    for (const PointId id : keyframe.points) {
      const MapPoint* a = before.Find(id);
      const MapPoint* b = after.Find(id);
      if (a == nullptr || b == nullptr) continue;
      changed += a->times_found != b->times_found || a->p_world != b->p_world ||
                 a->marked != b->marked || a->dynamic_frames != b->dynamic_frames;
    }
  }
  return changed;
}

// The runs reported after the held results were applied (polls TakeUnreportedRuns, 10 s at most).
int WaitForAppliedRuns(Slam* slam) {
  for (int ms = 0; ms < 10000; ++ms) {
    const std::vector<BackEndStatus> runs = slam->TakeUnreportedRuns();
    if (!runs.empty())
      return static_cast<int>(std::count_if(runs.begin(), runs.end(),
                                            [](const BackEndStatus& run) { return run.ba.ran; }));
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ADD_FAILURE() << "the held run was never applied";
  return 0;
}

// What tracking changed while a run was in flight (from `at_copy` to `before`) must survive the
// run's Apply (`after`): unmarked points that tracking re-positioned stay unmarked where it put
// them, and no point's count of dynamic frames goes back. Returns the number of such unmarked
// points checked.
int FrontEndUpdatesKept(const Map& at_copy, const Map& before, const Map& after) {
  int unmarked = 0;
  for (const KeyFrame& keyframe : before.window()) {
    for (const PointId id : keyframe.points) {
      const MapPoint* copied = at_copy.Find(id);
      const MapPoint* a = before.Find(id);
      const MapPoint* b = after.Find(id);
      if (a == nullptr || b == nullptr) continue;
      EXPECT_GE(b->dynamic_frames, a->dynamic_frames) << "point " << id;
      if (a->marked || copied == nullptr || copied->p_world == a->p_world) continue;
      ++unmarked;
      EXPECT_FALSE(b->marked) << "point " << id;
      EXPECT_EQ(b->p_world, a->p_world) << "point " << id;
    }
  }
  return unmarked;
}

// Takes Slam::MapSnapshot() about every millisecond on a thread of its own until destroyed: a
// reader of the map beside tracking, as the node's services are.
class SnapshotReader {
 public:
  explicit SnapshotReader(const Slam* slam)
      : thread_([this, slam] {
          while (!done_) {
            snapshots_ += slam->MapSnapshot().window().empty() ? 0 : 1;
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
          }
        }) {}
  ~SnapshotReader() {
    done_ = true;
    thread_.join();
  }
  int snapshots() const { return snapshots_; }

 private:
  std::atomic<bool> done_{false};
  std::atomic<int> snapshots_{0};
  std::thread thread_;
};

// A dynamic scene (walkers: their points are matched, re-positioned, unmarked and re-marked by
// every frame) with a back-end run in flight while tracking goes on: the run over the first three
// keyframes copies its window, works on it and holds its results until kInFlightUntil, then
// applies them; later runs overlap tracking freely. From the release on, another thread reads
// the map about every millisecond, so that the apply meets a reader whatever the scheduler does.
// Frames come 5 ms apart: without a gap the tracking thread takes the lock again before the
// waiting back-end thread gets it (measured: the run's copy waited 14 frames). Under
// ThreadSanitizer (CI) this fails when the back end's copy or apply step does not take the map
// mutex (checked once each by taking the lock out).
TEST(SlamThreads, MapChangesWhileARunIsInFlight) {
  constexpr int kWalkingFrames = 60, kInFlightUntil = 30;
  const test::RenderedSequence& walking = test::SharedSequence("walking", kWalkingFrames);
  Slam slam(BackEndOn(), BackEndMode::kThreaded);
  SlamTestAccess::HoldBackEnd(&slam, true);
  SlamTestAccess::HoldBackEndResults(&slam, true);
  int next = 0, keyframes = 0;
  while (keyframes < 3 && next < kInFlightUntil) {
    keyframes += slam.ProcessFrame(walking.frames[next++]).keyframe;
  }
  ASSERT_EQ(keyframes, 3);
  // The run over three keyframes starts; its results are held.
  SlamTestAccess::HoldBackEnd(&slam, false);
  int in_flight = 0, with_pose = next, delivered = 0, queued = keyframes;
  std::unique_ptr<Map> at_copy;
  std::unique_ptr<SnapshotReader> reader;
  Trajectory estimated;
  for (; next < kWalkingFrames; ++next) {
    if (next == kInFlightUntil) {
      ASSERT_NE(at_copy, nullptr) << "the run never copied its window";
      const Map before_apply = slam.MapSnapshot();
      EXPECT_GT(ChangedPoints(*at_copy, before_apply), 0);
      reader = std::make_unique<SnapshotReader>(&slam);
      SlamTestAccess::HoldBackEnd(&slam, true);  // no later run between the two snapshots
      SlamTestAccess::HoldBackEndResults(&slam, false);
      delivered += WaitForAppliedRuns(&slam);
      EXPECT_GT(FrontEndUpdatesKept(*at_copy, before_apply, slam.MapSnapshot()), 0);
      SlamTestAccess::HoldBackEnd(&slam, false);
    }
    const FrameResult r = slam.ProcessFrame(walking.frames[next]);
    with_pose += r.has_pose;
    delivered += r.backend_thread.delivered && r.backend.ba.ran;
    if (r.has_pose) estimated.push_back({r.stamp_s, r.T_world_camera});
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    // The backlog fell below the keyframes queued since the start: the run took them and copied
    // its window before this frame began, and its results are held: this frame ran with the run
    // in flight.
    queued += r.keyframe;
    if (next < kInFlightUntil && (at_copy != nullptr || r.backend_thread.backlog < queued)) {
      in_flight += at_copy != nullptr;
      if (at_copy == nullptr) at_copy = std::make_unique<Map>(slam.MapSnapshot());
    }
  }
  slam.WaitForBackEnd();
  EXPECT_GT(reader->snapshots(), 0);
  reader.reset();
  for (const BackEndStatus& run : slam.TakeUnreportedRuns()) delivered += run.ba.ran;
  EXPECT_GE(in_flight, 10);
  EXPECT_GE(delivered, 1);
  EXPECT_EQ(with_pose, kWalkingFrames);
  EXPECT_LT(test::AteRmse(estimated, walking.groundtruth), 0.05);
}

}  // namespace
}  // namespace dslam
