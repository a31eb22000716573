// Slam's keyframe observers (keyframe_observer.h): every keyframe in order with shared images and
// its labels, the window's poses, resets in order with the keyframes, the same in both modes, and
// the calls never overlapping and never on the tracking thread when threaded. Also run under
// ThreadSanitizer by scripts/sanitize.sh (binary test_slam_threads).
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/backend/slam.h"
#include "support/rendered_sequence.h"
#include "support/slam_test_access.h"

namespace dslam {
namespace {

// The sequence of every test of this file: test::SharedSequence(kScene, kFrames).
constexpr char kScene[] = "static_room";
constexpr int kFrames = 40;

// Records what Slam hands over: "k<id>" per keyframe, "r0"/"r1" per reset (kKeepPose/kNewWorld).
class Recorder : public KeyFrameObserver {
 public:
  void OnKeyFrames(const std::vector<KeyFrameRecord>& added,
                   const std::vector<KeyFramePose>& window) override {
    Enter();
    for (const KeyFrameRecord& keyframe : added) {
      events.push_back("k" + std::to_string(keyframe.id));
      records.push_back(keyframe);
    }
    last_window = window;
    Leave();
  }
  void OnReset(ResetMode mode) override {
    Enter();
    events.push_back(mode == ResetMode::kNewWorld ? "r1" : "r0");
    Leave();
  }
  void OnCorrection(const std::vector<KeyFramePose>& keyframes) override {
    Enter();
    events.push_back("c" + std::to_string(keyframes.size()));
    corrected = keyframes;
    Leave();
  }

  std::vector<std::string> events;
  std::vector<KeyFrameRecord> records;
  std::vector<KeyFramePose> last_window;
  std::vector<KeyFramePose> corrected;   ///< of the last OnCorrection
  std::vector<std::thread::id> threads;  ///< the thread of each call
  bool overlapped = false;

 private:
  void Enter() {
    const std::lock_guard<std::mutex> lock(mutex_);
    overlapped |= inside_;
    inside_ = true;
    threads.push_back(std::this_thread::get_id());
  }
  void Leave() {
    const std::lock_guard<std::mutex> lock(mutex_);
    inside_ = false;
  }
  std::mutex mutex_;
  bool inside_ = false;
};

struct Fed {
  std::vector<std::string> keyframes;  ///< "k<id>" of every FrameResult with keyframe set
  std::vector<FrameResult> results;
};

// Frames [begin, end) through `slam`, each with `request`.
void Feed(Slam* slam, int begin, int end, const FrameRequest& request, Fed* run) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  for (int i = begin; i < end; ++i) {
    const FrameResult r = slam->ProcessFrame(room.frames[i], request);
    if (r.keyframe) {
      run->keyframes.push_back("k" + std::to_string(slam->MapSnapshot().window().back().id));
    }
    run->results.push_back(r);
  }
}

Config WithBackEnd(bool on) {
  Config config;
  config.backend.enabled = on;
  config.backend.ba_fixed_keyframes = 1;
  return config;
}

TEST(KeyFrameObserver, ReceivesEveryKeyFrameWithSharedImagesAndLabels) {
  auto recorder = std::make_shared<Recorder>();
  Slam slam(WithBackEnd(true), BackEndMode::kSynchronous, RefinedPoseRecording::kOn, {recorder});
  Fed run;
  Feed(&slam, 0, kFrames, FrameRequest{true, false}, &run);
  ASSERT_GE(run.keyframes.size(), 4u);
  EXPECT_EQ(recorder->events, run.keyframes);
  EXPECT_FALSE(recorder->overlapped);
  for (const std::thread::id id : recorder->threads) EXPECT_EQ(id, std::this_thread::get_id());
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  size_t k = 0;
  for (size_t i = 0; i < run.results.size(); ++i) {
    if (!run.results[i].keyframe) continue;
    const KeyFrameRecord& record = recorder->records[k++];
    // A shallow copy: the very pixels of the frame handed in.
    EXPECT_EQ(record.frame.depth_m.data, room.frames[i].depth_m.data);
    EXPECT_EQ(record.frame.colour.data, room.frames[i].colour.data);
    EXPECT_TRUE(record.T_world_camera.isApprox(run.results[i].T_world_camera));
    EXPECT_EQ(record.points.size(), run.results[i].points.size());
  }
  // The window's poses as the back end left them.
  const Map map = slam.MapSnapshot();
  ASSERT_EQ(recorder->last_window.size(), map.window().size());
  for (size_t i = 0; i < map.window().size(); ++i) {
    EXPECT_EQ(recorder->last_window[i].id, map.window()[i].id);
    EXPECT_TRUE(
        recorder->last_window[i].T_world_camera.isApprox(map.window()[i].T_world_camera));
  }
}

TEST(KeyFrameObserver, LabelsArriveWhenTheCallerAsksForNoPoints) {
  auto recorder = std::make_shared<Recorder>();
  Slam slam(WithBackEnd(false), BackEndMode::kSynchronous, RefinedPoseRecording::kOn, {recorder});
  Fed run;
  Feed(&slam, 0, kFrames, FrameRequest{false, false}, &run);
  for (const FrameResult& r : run.results) EXPECT_TRUE(r.points.empty());
  size_t labelled = 0;  // keyframes after the first have matched points
  for (const KeyFrameRecord& record : recorder->records) labelled += !record.points.empty();
  EXPECT_EQ(labelled + 1, recorder->records.size());
}

TEST(KeyFrameObserver, ThreadedDeliversTheSameOnTheBackEndThread) {
  for (const bool backend : {true, false}) {
    auto recorder = std::make_shared<Recorder>();
    Slam slam(WithBackEnd(backend), BackEndMode::kThreaded, RefinedPoseRecording::kOn, {recorder});
    Fed run;
    Feed(&slam, 0, kFrames, FrameRequest{}, &run);
    slam.WaitForBackEnd();
    EXPECT_EQ(recorder->events, run.keyframes) << "back end " << backend;
    EXPECT_FALSE(recorder->overlapped);
    for (const std::thread::id id : recorder->threads) EXPECT_NE(id, std::this_thread::get_id());
    EXPECT_EQ(recorder->last_window.size(), slam.MapSnapshot().window().size());
  }
}

TEST(KeyFrameObserver, ResetsArriveInOrderWithTheKeyFrames) {
  for (const BackEndMode mode : {BackEndMode::kSynchronous, BackEndMode::kThreaded}) {
    auto first = std::make_shared<Recorder>(), second = std::make_shared<Recorder>();
    Slam slam(WithBackEnd(true), mode, RefinedPoseRecording::kOn, {first, second});
    SlamTestAccess::HoldBackEnd(&slam, true);  // threaded: all queues, then one delivery
    Fed run;
    Feed(&slam, 0, 15, FrameRequest{}, &run);
    std::vector<std::string> expected = run.keyframes;
    slam.Reset(ResetMode::kKeepPose);
    expected.push_back("r0");
    run.keyframes.clear();
    Feed(&slam, 15, 25, FrameRequest{}, &run);
    expected.insert(expected.end(), run.keyframes.begin(), run.keyframes.end());
    // Time going backwards: a new world before the keyframe of the frame that found it.
    run.keyframes.clear();
    Feed(&slam, 0, 5, FrameRequest{}, &run);
    ASSERT_TRUE(run.results[run.results.size() - 5].reset);
    expected.push_back("r1");
    expected.insert(expected.end(), run.keyframes.begin(), run.keyframes.end());
    slam.Reset(ResetMode::kNewWorld);
    expected.push_back("r1");
    slam.WaitForBackEnd();
    EXPECT_EQ(first->events, expected);
    EXPECT_EQ(second->events, expected);
  }
}

// The map after frames 0-14 and the correction made then: the newest keyframe moved 10 cm
// along x.
struct NewestCorrected {
  Map before;
  int newest = -1;
  Eigen::Isometry3d moved = Eigen::Isometry3d::Identity();
  bool corrected = false;  ///< CorrectKeyFrames accepted it
};

// Feeds frames 0-14 to `slam`, waits for its back end and corrects the newest keyframe
// (CorrectKeyFrames, as loop closing does), without a frame after it.
NewestCorrected CorrectNewestKeyFrame(Slam* slam) {
  Fed run;
  Feed(slam, 0, 15, FrameRequest{}, &run);
  slam->WaitForBackEnd();
  NewestCorrected out{slam->MapSnapshot()};
  out.newest = out.before.window().back().id;
  out.moved = out.before.window().back().T_world_camera;
  out.moved.translation().x() += 0.1;
  out.corrected = slam->CorrectKeyFrames({{out.newest, out.moved}});
  return out;
}

TEST(KeyFrameObserver, ACorrectionArrivesAfterTheKeyFramesWithEveryCorrectedPose) {
  for (const BackEndMode mode : {BackEndMode::kSynchronous, BackEndMode::kThreaded}) {
    auto recorder = std::make_shared<Recorder>();
    Slam slam(WithBackEnd(false), mode, RefinedPoseRecording::kOn, {recorder});
    const auto [map, newest, moved, corrected] = CorrectNewestKeyFrame(&slam);
    ASSERT_TRUE(corrected);
    const size_t keyframes = map.num_keyframes();
    slam.WaitForBackEnd();  // delivers it
    ASSERT_FALSE(recorder->events.empty());
    EXPECT_EQ(recorder->events.back(), "c" + std::to_string(keyframes));
    ASSERT_FALSE(recorder->corrected.empty());
    bool found = false;
    for (const KeyFramePose& pose : recorder->corrected) {
      if (pose.id != newest) continue;
      found = true;
      EXPECT_TRUE(pose.T_world_camera.isApprox(moved, 1e-9));
    }
    EXPECT_TRUE(found);
    // A reset after a correction drops it: the observers never see the old world's poses.
    ASSERT_TRUE(slam.CorrectKeyFrames({{newest, moved}}));
    slam.Reset(ResetMode::kNewWorld);
    slam.WaitForBackEnd();
    EXPECT_EQ(recorder->events.back(), "r1");
  }
}

// Runs `wait` on a thread of its own and fails (ending the process: the hung thread cannot be
// joined) when it has not returned within `limit_s`.
void ReturnsWithin(double limit_s, const std::function<void()>& wait) {
  std::atomic<bool> done{false};
  std::thread waiter([&] {
    wait();
    done = true;
  });
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_s);
  while (!done && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (!done) {
    ADD_FAILURE() << "did not return within " << limit_s << " s";
    std::fflush(nullptr);
    std::_Exit(1);
  }
  waiter.join();
}

// A loop closed after the last frame (loop closing's thread corrects while no frame follows):
// WaitForBackEnd delivers the correction and returns, in both modes.
TEST(KeyFrameObserver, WaitForBackEndReturnsAfterACorrectionWithoutAFrame) {
  for (const BackEndMode mode : {BackEndMode::kSynchronous, BackEndMode::kThreaded}) {
    auto recorder = std::make_shared<Recorder>();
    Slam slam(WithBackEnd(true), mode, RefinedPoseRecording::kOn, {recorder});
    const NewestCorrected correction = CorrectNewestKeyFrame(&slam);
    ASSERT_TRUE(correction.corrected);
    const Map& map = correction.before;
    ReturnsWithin(20.0, [&] { slam.WaitForBackEnd(); });
    ASSERT_FALSE(recorder->events.empty());
    EXPECT_EQ(recorder->events.back(), "c" + std::to_string(map.num_keyframes()));
  }
}

// Corrects the map from inside OnKeyFrames once armed, as synchronous loop closing does when the
// last frame's keyframe closes a loop.
class CorrectingObserver : public KeyFrameObserver {
 public:
  void OnKeyFrames(const std::vector<KeyFrameRecord>& added,
                   const std::vector<KeyFramePose>& window) override {
    if (!armed || added.empty() || window.empty()) return;
    armed = false;
    Eigen::Isometry3d moved = window.back().T_world_camera;
    moved.translation().y() += 0.05;
    corrected = slam->CorrectKeyFrames({{window.back().id, moved}});
  }
  void OnReset(ResetMode) override {}
  Slam* slam = nullptr;
  std::atomic<bool> armed{false};
  bool corrected = false;
};

TEST(KeyFrameObserver, ALoopClosedAtTheLastKeyFrameReachesTheObserversAndTheWaitReturns) {
  for (const BackEndMode mode : {BackEndMode::kSynchronous, BackEndMode::kThreaded}) {
    auto corrector = std::make_shared<CorrectingObserver>();
    auto recorder = std::make_shared<Recorder>();
    Slam slam(WithBackEnd(true), mode, RefinedPoseRecording::kOn, {corrector, recorder});
    corrector->slam = &slam;
    Fed run;
    Feed(&slam, 0, 10, FrameRequest{}, &run);
    slam.WaitForBackEnd();
    corrector->armed = true;
    for (int i = 10; i < kFrames && corrector->armed; ++i) Feed(&slam, i, i + 1, {}, &run);
    ReturnsWithin(20.0, [&] { slam.WaitForBackEnd(); });
    EXPECT_TRUE(corrector->corrected);
    ASSERT_FALSE(recorder->events.empty());
    EXPECT_EQ(recorder->events.back().front(), 'c');
  }
}

// Throws from every call.
class FailingObserver : public KeyFrameObserver {
 public:
  void OnKeyFrames(const std::vector<KeyFrameRecord>&, const std::vector<KeyFramePose>&) override {
    throw std::runtime_error("disk full");
  }
  void OnReset(ResetMode) override { throw std::runtime_error("reset failed"); }
  std::string name() const override { return "failing"; }
};

// An observer's error is reported once, under its name, and neither reaches ProcessFrame (which
// would skip a good frame) nor stops the observers after it.
TEST(KeyFrameObserver, AnObserversErrorIsReportedOnceAndTheOthersGetEveryEvent) {
  for (const BackEndMode mode : {BackEndMode::kSynchronous, BackEndMode::kThreaded}) {
    auto recorder = std::make_shared<Recorder>();
    Slam slam(WithBackEnd(true), mode, RefinedPoseRecording::kOn,
              {std::make_shared<FailingObserver>(), recorder});
    Fed run;
    EXPECT_NO_THROW(Feed(&slam, 0, 20, FrameRequest{}, &run));
    EXPECT_NO_THROW(slam.WaitForBackEnd());
    ASSERT_GE(run.keyframes.size(), 2u);
    EXPECT_EQ(recorder->events, run.keyframes);
    const std::vector<ReportedError> errors = slam.errors()->TakeNew();
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(static_cast<int64_t>(errors.size()), slam.errors()->count());
    EXPECT_EQ(errors.front().where, "failing");
    EXPECT_EQ(errors.front().what, "disk full");
    EXPECT_TRUE(slam.errors()->TakeNew().empty());
  }
}

}  // namespace
}  // namespace dslam
