// Localisation only in a saved keyframe map (StartInKeyFrameMap with
// LoadedMapUse::kLocalisationOnly), with the back end and loop closing on: the first run maps
// frames 0-59 of the synthetic static_room, the second runs frames 45-89 in that map. The loaded
// keyframes and points must come out of the run bit for bit as they were loaded (compared as
// file bytes: every saved field), the map must hold no more than the loaded keyframes and the
// window, and every pose must be in the loaded map's world. The same run extending the map
// changes the loaded part, so that the comparison is not vacuous. Tolerances are measured values
// with margin (comment at each bound).
#include <algorithm>
#include <memory>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "dslam/loop_closing/loop_closing.h"
#include "dslam/map_file/keyframe_map_session.h"
#include "support/rendered_sequence.h"

namespace dslam {
namespace {

constexpr int kFrames = 90;
constexpr int kFirstRunFrames = 60;  // frames 0-59 map the room
constexpr int kSecondRunStart = 45;  // frames 45-89 run in that map
constexpr int kWindow = 4;           // tracking.window_keyframes: new keyframes leave it soon

std::shared_ptr<const Vocabulary> DefaultVocabulary() {
  static const auto vocabulary =
      std::make_shared<const Vocabulary>(Vocabulary::Load(DefaultVocabularyPath()));
  return vocabulary;
}

Config BackEndConfig() {
  Config config;
  config.backend.enabled = true;  // loop_closing.enabled is on by default
  config.tracking.window_keyframes = kWindow;
  config.tracking.keyframe_max_interval = 3;  // a keyframe every 3 frames: 15 in the second run
  return config;
}

KeyFrameMapFile FirstRunFile(const test::RenderedSequence& room) {
  Slam slam(BackEndConfig());
  for (int i = 0; i < kFirstRunFrames; ++i) slam.ProcessFrame(room.frames[i]);
  return KeyFrameMapOf(slam, *room.frames[0].camera, DefaultVocabulary()->identity(), nullptr);
}

/// The bytes of a keyframe map file of `file`'s camera and vocabulary holding the keyframes and
/// points of `contents` whose ids `file` has (the loaded part), without images.
std::string LoadedPartBytes(const KeyFrameMapFile& file, const MapContents& contents) {
  std::set<int> keyframe_ids;
  std::set<PointId> point_ids;
  for (const KeyFrame& keyframe : file.contents.keyframes) keyframe_ids.insert(keyframe.id);
  for (const MapPoint& point : file.contents.points) point_ids.insert(point.id);
  KeyFrameMapFile part{file.camera, file.vocabulary_identity, {}, {}, file.settings};
  for (const KeyFrame& keyframe : contents.keyframes) {
    if (keyframe_ids.count(keyframe.id) != 0) part.contents.keyframes.push_back(keyframe);
  }
  for (const MapPoint& point : contents.points) {
    if (point_ids.count(point.id) != 0) part.contents.points.push_back(point);
  }
  return SerialiseKeyFrameMap(part);
}

struct SecondRun {
  int posed = 0;
  double worst_m = 0.0;        ///< [m] largest position error in the loaded map's world
  size_t most_keyframes = 0;   ///< the map's keyframes after any frame
  int new_keyframes = 0;       ///< frames that became keyframes
  int local_mapping_runs = 0;  ///< local BA runs
  size_t loops = 0;
  MapContents after;  ///< the map at the end
};

SecondRun RunInMap(const test::RenderedSequence& room, const KeyFrameMapFile& file,
                   LoadedMapUse use) {
  const Config config = BackEndConfig();
  auto loop_closing = std::make_shared<LoopClosing>(config, DefaultVocabulary());
  Slam slam(config, BackEndMode::kSynchronous, RefinedPoseRecording::kOn, {loop_closing});
  loop_closing->Attach(&slam);
  EXPECT_EQ(StartInKeyFrameMap(file, room.frames[0].camera, DefaultVocabulary(), 10.0, &slam, use),
            "");
  const Eigen::Isometry3d T_world_truth = room.groundtruth[0].T_world_camera.inverse();
  SecondRun run;
  for (int i = kSecondRunStart; i < kFrames; ++i) {
    const FrameResult result = slam.ProcessFrame(room.frames[i]);
    slam.ReadMap([&](const Map& map) {
      run.most_keyframes = std::max(run.most_keyframes, map.num_keyframes());
    });
    run.new_keyframes += result.keyframe ? 1 : 0;
    run.local_mapping_runs += result.backend.ba.ran ? 1 : 0;
    if (!result.has_pose) continue;
    ++run.posed;
    const Eigen::Isometry3d truth = T_world_truth * room.groundtruth[i].T_world_camera;
    run.worst_m =
        std::max(run.worst_m, (result.T_world_camera.translation() - truth.translation()).norm());
  }
  slam.ReadMap([&](const Map& map) { run.after = map.Contents(); });
  run.loops = loop_closing->loops().size();
  return run;
}

TEST(LocalisationOnly, TheLoadedMapStaysBitForBitAndTheMapStaysBounded) {
  const test::RenderedSequence& room = test::SharedSequence("static_room", kFrames);
  const KeyFrameMapFile file = FirstRunFile(room);
  const size_t loaded_keyframes = file.contents.keyframes.size();
  ASSERT_GE(loaded_keyframes, 5u);
  // As loaded: Map::FromContents drops the keyframes' references to points the first run culled.
  const MapContents as_loaded = Map::FromContents(file.contents).Contents();
  const std::string loaded = LoadedPartBytes(file, as_loaded);

  const SecondRun only = RunInMap(room, file, LoadedMapUse::kLocalisationOnly);
  EXPECT_EQ(only.posed, kFrames - kSecondRunStart);  // measured: the first frame localises
  EXPECT_LT(only.worst_m, 0.012);                    // measured 6.0 mm
  EXPECT_TRUE(LoadedPartBytes(file, only.after) == loaded) << "the loaded map changed";
  EXPECT_EQ(only.loops, 0u);
  EXPECT_GT(only.local_mapping_runs, 0);   // the back end ran on the temporary keyframes
  EXPECT_GT(only.new_keyframes, kWindow);  // measured 15: most left the window and the map
  EXPECT_LE(only.most_keyframes, loaded_keyframes + kWindow);  // measured 20 + 4
  EXPECT_LE(only.after.keyframes.size(), loaded_keyframes + kWindow);

  const SecondRun extend = RunInMap(room, file, LoadedMapUse::kExtend);
  EXPECT_EQ(extend.posed, kFrames - kSecondRunStart);
  EXPECT_FALSE(LoadedPartBytes(file, extend.after) == loaded);  // refined, relabelled, culled
  EXPECT_GT(extend.after.keyframes.size(), loaded_keyframes + kWindow);  // measured 29
}

}  // namespace
}  // namespace dslam
