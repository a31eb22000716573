// Loop closing on a whole synthetic sequence (`room_tour` seed 1: one lap of a room and back into
// its first views, a walker crossing the right wall in both laps): Slam with the back end and
// LoopClosing as its keyframe observer, against the same run without loop closing; and with the
// lens covered for 80 frames of the second lap, relocalised in the whole keyframe map through
// loop closing's place recognition. Tolerances are measured values with margin (comment at each
// bound).
#include <gtest/gtest.h>

#include "dslam/backend/slam.h"
#include "dslam/eval/loop_check.h"
#include "dslam/loop_closing/loop_closing.h"
#include "dslam/place_recognition/vocabulary.h"
#include "support/ate.h"
#include "support/rendered_sequence.h"

namespace dslam {
namespace {

constexpr int kFrames = 728;  // one lap (548 frames) and 6 s into the first views again

struct TourRun {
  double refined_ate_m = 0.0;
  std::vector<ClosedLoop> loops;
  int initialisations = 0;  ///< frames in state kInitialised (the first, and re-initialisations)
};

/// room_tour seed 1, rendered once for the tests of this binary (2 GB of images: not written to
/// the scenes shared by the test binaries, none other uses it).
const test::RenderedSequence& Tour() {
  static const test::RenderedSequence tour = test::RenderSequence("room_tour", kFrames, 1, false);
  return tour;
}

TourRun RunRoomTour(const std::vector<RgbdFrame>& frames, bool loop_closing) {
  Config config = test::SensorConfig(Tour());
  config.backend.enabled = true;
  std::vector<std::shared_ptr<KeyFrameObserver>> observers;
  std::shared_ptr<LoopClosing> closer;
  if (loop_closing) {
    closer = std::make_shared<LoopClosing>(
        config, std::make_shared<const Vocabulary>(Vocabulary::Load(DefaultVocabularyPath())));
    observers.push_back(closer);
  }
  Slam slam(config, BackEndMode::kSynchronous, RefinedPoseRecording::kOn, observers);
  if (closer) closer->Attach(&slam);
  TourRun run;
  test::TrackAll(&slam, frames, [&run](size_t, const FrameResult& result) {
    run.initialisations += result.state == TrackingState::kInitialised;
  });
  run.refined_ate_m = test::AteRmse(slam.RefinedPoses(), Tour().groundtruth);
  if (closer) run.loops = closer->loops();
  return run;
}

TEST(LoopClosingRegression, RoomTourClosesTrueLoopsAndTheLapComesTogether) {
  const test::RenderedSequence& tour = Tour();
  const TourRun off = RunRoomTour(tour.frames, false);
  const TourRun on = RunRoomTour(tour.frames, true);
  // Synchronous, so deterministic: frames 556, 651 and 708 see 13, 103, 165 again.
  ASSERT_EQ(on.loops.size(), 3u);
  std::vector<LoopRecord> records;
  for (const ClosedLoop& loop : on.loops) {
    records.push_back(
        {loop.detection.query_stamp_s, loop.detection.match_stamp_s, loop.detection.T_match_query});
  }
  const LoopCheck check = CheckLoops(records, tour.groundtruth, LoopCheckOptions());
  EXPECT_EQ(check.checked, static_cast<int>(records.size()));
  EXPECT_EQ(check.false_loops, 0);     // measured errors <= 8 mm, 0.21 deg
  EXPECT_GT(off.refined_ate_m, 0.15);  // measured 0.21 m
  EXPECT_LT(on.refined_ate_m, 0.14);   // measured 0.07 m
  EXPECT_LT(on.refined_ate_m, 0.5 * off.refined_ate_m);
  EXPECT_EQ(on.initialisations, 1);
}

TEST(LoopClosingRegression, ALensCoveredOnTheSecondLapIsRelocalisedInTheWholeMap) {
  // Frames 560-639 black without depth: the camera walks 1.2 m meanwhile, into views of the
  // first lap whose keyframes left the window long ago. Relocalisation in the window fails; the
  // places loop closing's vocabulary names in the whole map (LoopClosing::Attach) find them.
  std::vector<RgbdFrame> frames = Tour().frames;  // shallow: the images are shared
  for (int i = 560; i < 640; ++i) {
    RgbdFrame& frame = frames[i];
    frame.colour = cv::Mat::zeros(frame.colour.size(), frame.colour.type());
    frame.depth_m = cv::Mat::zeros(frame.depth_m.size(), frame.depth_m.type());
  }
  const TourRun on = RunRoomTour(frames, true);
  EXPECT_EQ(on.initialisations, 1);   // without the whole map's places: re-initialised at 640
  EXPECT_LT(on.refined_ate_m, 0.12);  // measured 0.040 m; re-initialised: 0.33 m
}

}  // namespace
}  // namespace dslam
