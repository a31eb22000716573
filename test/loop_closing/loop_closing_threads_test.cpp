// Loop closing beside tracking (threaded Slam): LoopClosing reads the map from the back-end
// thread (Slam::ReadMap) while the caller tracks, and keyframe corrections
// (Slam::CorrectKeyFrames) arrive from that thread between frames and during local-mapping runs.
// Run under ThreadSanitizer by scripts/sanitize.sh (CI).
#include <atomic>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "dslam/backend/slam.h"
#include "dslam/loop_closing/loop_closing.h"
#include "dslam/place_recognition/vocabulary.h"
#include "support/rendered_sequence.h"

namespace dslam {
namespace {

// After each delivery, moves every keyframe of the map by 1 mm along x, as a loop correction
// does (from the back-end thread, the map lock not held by the caller).
class Corrector : public KeyFrameObserver {
 public:
  void Attach(Slam* slam) { slam_ = slam; }
  void OnKeyFrames(const std::vector<KeyFrameRecord>& added,
                   const std::vector<KeyFramePose>& window) override {
    if (added.empty() || slam_ == nullptr) return;
    std::map<int, Eigen::Isometry3d> corrected;
    slam_->ReadMap([&](const Map& map) {
      for (const KeyFrame& keyframe : map.window()) {
        corrected[keyframe.id] = Eigen::Translation3d(0.001, 0.0, 0.0) * keyframe.T_world_camera;
      }
    });
    if (!slam_->CorrectKeyFrames(corrected)) return;
    ++corrections_;
    // The correction reached the map: every corrected keyframe is where it was sent (this is
    // the back-end thread, so no local-mapping run applies in between).
    slam_->ReadMap([&](const Map& map) {
      for (const auto& [id, T_world_camera] : corrected) {
        const KeyFrame* keyframe = map.FindKeyFrame(id);
        missed_ += keyframe != nullptr && !keyframe->T_world_camera.isApprox(T_world_camera, 1e-9);
      }
    });
  }
  void OnReset(ResetMode) override {}
  int corrections() const { return corrections_; }
  int missed() const { return missed_; }  ///< corrected keyframes not at their corrected pose

 private:
  Slam* slam_ = nullptr;
  std::atomic<int> corrections_{0};
  std::atomic<int> missed_{0};
};

/// The default configuration with the back end on.
Config BackEndConfig() {
  Config config;
  config.backend.enabled = true;
  return config;
}

/// Loop closing on its own thread, with the committed vocabulary.
std::shared_ptr<LoopClosing> ThreadedLoopClosing(const Config& config) {
  return std::make_shared<LoopClosing>(
      config, std::make_shared<const Vocabulary>(Vocabulary::Load(DefaultVocabularyPath())),
      WorkerMode::kThreaded);
}

TEST(LoopClosingThreads, DetectionAndCorrectionsRunBesideTracking) {
  const test::RenderedSequence& room = test::SharedSequence("static_room", 60);
  const Config config = BackEndConfig();
  const std::shared_ptr<LoopClosing> closer = ThreadedLoopClosing(config);
  auto corrector = std::make_shared<Corrector>();
  Slam slam(config, BackEndMode::kThreaded, RefinedPoseRecording::kOn, {closer, corrector});
  closer->Attach(&slam);
  corrector->Attach(&slam);
  int with_pose = 0;
  for (const RgbdFrame& frame : room.frames) with_pose += slam.ProcessFrame(frame).has_pose;
  slam.WaitForBackEnd();
  closer->Wait();
  EXPECT_EQ(with_pose, 60);
  EXPECT_GE(corrector->corrections(), 1);  // deliveries group the keyframes made meanwhile
  EXPECT_EQ(corrector->missed(), 0);
  EXPECT_GE(closer->times_ms().size(), 3u);
  EXPECT_TRUE(closer->loops().empty());  // one view of a room: nothing seen twice
  EXPECT_EQ(slam.RefinedPoses().size(), 60u);
}

TEST(LoopClosingThreads, SlamStopsLoopClosingBeforeItIsDestroyed) {
  // Slam destroyed while keyframes may still wait for loop closing's thread: ~Slam's OnStop
  // skips them and waits for the one in progress, so nothing calls the destroyed Slam (the
  // sanitizers' builds check that), and loop closing stays usable and idle after it.
  const test::RenderedSequence& room = test::SharedSequence("static_room", 60);
  const Config config = BackEndConfig();
  const std::shared_ptr<LoopClosing> closer = ThreadedLoopClosing(config);
  {
    Slam slam(config, BackEndMode::kThreaded, RefinedPoseRecording::kOn, {closer});
    closer->Attach(&slam);
    for (const RgbdFrame& frame : room.frames) slam.ProcessFrame(frame);
  }
  const LoopWork after_stop = closer->work();
  closer->Wait();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const LoopWork later = closer->work();
  EXPECT_EQ(later.keyframes, after_stop.keyframes);
  EXPECT_EQ(later.loops, 0);
}

}  // namespace
}  // namespace dslam
