// Starting in a saved keyframe map (Slam::StartInMap with MapPlaces): a second run on a later
// stretch of the same synthetic sequence has no pose until it relocalises in the first run's
// map, then reports every pose in the first run's world frame. Tolerances are measured values
// with margin (comment at each bound).
#include <gtest/gtest.h>

#include "dslam/backend/slam.h"
#include "dslam/core/geometry.h"
#include "dslam/loop_closing/map_places.h"
#include "dslam/place_recognition/vocabulary.h"
#include "support/rendered_sequence.h"

namespace dslam {
namespace {

constexpr int kFrames = 90;
constexpr int kFirstRunFrames = 60;  // frames 0-59 map the room
constexpr int kSecondRunStart = 45;  // frames 45-89 start in that map

std::shared_ptr<const Vocabulary> DefaultVocabulary() {
  static const auto vocabulary =
      std::make_shared<const Vocabulary>(Vocabulary::Load(DefaultVocabularyPath()));
  return vocabulary;
}

Map FirstRunMap(const test::RenderedSequence& room, const Config& config) {
  Slam slam(config);
  for (int i = 0; i < kFirstRunFrames; ++i) slam.ProcessFrame(room.frames[i]);
  Map map;
  slam.ReadMap([&](const Map& live) { map = Map::FromContents(live.Contents()); });
  return map;
}

TEST(Localisation, ASecondRunLocalisesInTheSavedMapAndKeepsItsWorldFrame) {
  const test::RenderedSequence& room = test::SharedSequence("static_room", kFrames);
  Config config;
  config.backend.enabled = true;
  Map saved = FirstRunMap(room, config);
  const size_t saved_keyframes = saved.num_keyframes();
  ASSERT_GE(saved_keyframes, 5u);

  Slam slam(config);
  slam.StartInMap(std::move(saved), std::make_shared<MapPlaces>(DefaultVocabulary()), 10.0);
  EXPECT_TRUE(slam.Localising());
  // The first run's world is its first camera: the truth in that frame.
  const Eigen::Isometry3d T_world_truth = room.groundtruth[0].T_world_camera.inverse();
  int first_posed = -1, posed = 0;
  double worst_m = 0.0;
  for (int i = kSecondRunStart; i < kFrames; ++i) {
    const FrameResult result = slam.ProcessFrame(room.frames[i]);
    if (!result.has_pose) {
      EXPECT_EQ(result.state, TrackingState::kLocalising);
      continue;
    }
    if (first_posed < 0) first_posed = i;
    ++posed;
    const Eigen::Isometry3d truth = T_world_truth * room.groundtruth[i].T_world_camera;
    worst_m = std::max(worst_m, (result.T_world_camera.translation() - truth.translation()).norm());
    EXPECT_LT(RotationAngleDeg(result.T_world_camera.linear().transpose() * truth.linear()), 1.0);
  }
  EXPECT_FALSE(slam.Localising());
  EXPECT_EQ(first_posed, kSecondRunStart);  // measured: the first frame localises
  EXPECT_EQ(posed, kFrames - kSecondRunStart);
  // The camera is 0.2-0.3 m from frame 0's pose here: a run in its own world would be that far.
  EXPECT_LT(worst_m, 0.012);  // measured 4 mm
  Map after;
  slam.ReadMap([&](const Map& live) { after = Map::FromContents(live.Contents()); });
  EXPECT_GT(after.num_keyframes(), saved_keyframes);  // the loaded map was extended
}

}  // namespace
}  // namespace dslam
