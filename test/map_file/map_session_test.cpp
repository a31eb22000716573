// A keyframe map file in a running Slam (keyframe_map_session.h) on a short static_room sequence
// rendered in-process: images kept for the map's keyframes, the file taken from the map, the
// loaded keyframes handed to the observers after the reset, and a file of another camera or
// other ORB or depth noise settings refused.
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/map_file/keyframe_map_session.h"
#include "support/rendered_sequence.h"

namespace dslam {
namespace {

constexpr int kFrames = 30;

std::shared_ptr<const Vocabulary> DefaultVocabulary() {
  static const auto vocabulary =
      std::make_shared<const Vocabulary>(Vocabulary::Load(DefaultVocabularyPath()));
  return vocabulary;
}

/// Records what the observers receive: resets as id -1, loaded keyframes as their ids.
class EventLog : public KeyFrameObserver {
 public:
  void OnKeyFrames(const std::vector<KeyFrameRecord>& added,
                   const std::vector<KeyFramePose>&) override {
    for (const KeyFrameRecord& record : added) {
      if (record.loaded) {
        events.push_back(record.id);
        points += record.points.size();
      }
    }
  }
  void OnReset(ResetMode) override { events.push_back(-1); }
  std::vector<int> events;
  size_t points = 0;
};

/// The map of frames [0, kFrames) with the images of its keyframes.
KeyFrameMapFile MappedRoom(const test::RenderedSequence& room) {
  auto keeper = std::make_shared<KeyFrameImageKeeper>();
  Slam slam(Config(), BackEndMode::kSynchronous, RefinedPoseRecording::kOn, {keeper});
  keeper->Attach(&slam);
  for (int i = 0; i < kFrames; ++i) slam.ProcessFrame(room.frames[i]);
  return KeyFrameMapOf(slam, *room.frames[0].camera, DefaultVocabulary()->identity(), keeper.get());
}

TEST(MapSession, TheFileHoldsTheMapAndTheImagesOfItsKeyFrames) {
  const test::RenderedSequence& room = test::SharedSequence("static_room", kFrames);
  const KeyFrameMapFile file = MappedRoom(room);
  ASSERT_GE(file.contents.keyframes.size(), 2u);
  EXPECT_EQ(file.images.size(), file.contents.keyframes.size());
  EXPECT_EQ(file.vocabulary_identity, DefaultVocabulary()->identity());
  const std::vector<KeyFrameRecord> records = LoadedKeyFrameRecords(file, room.frames[0].camera);
  ASSERT_EQ(records.size(), file.contents.keyframes.size());
  const KeyFrame& first = file.contents.keyframes.front();
  EXPECT_EQ(records.front().id, first.id);
  EXPECT_TRUE(records.front().T_world_camera.isApprox(first.T_world_camera));
  std::set<PointId> in_map;
  for (const MapPoint& point : file.contents.points) in_map.insert(point.id);
  size_t measured_in_map = 0;
  for (const auto& entry : first.measurements.by_point)
    measured_in_map += in_map.count(entry.first);
  EXPECT_EQ(records.front().points.size(), measured_in_map);  // culled points are left out
  EXPECT_GT(measured_in_map, 100u);
  for (const ObservedPoint& point : records.front().points) {
    EXPECT_TRUE(room.frames[0].camera->InImage(point.uv_raw)) << point.uv_raw.transpose();
  }
}

TEST(MapSession, ObserversGetTheLoadedKeyFramesAfterTheReset) {
  const test::RenderedSequence& room = test::SharedSequence("static_room", kFrames);
  const KeyFrameMapFile file = MappedRoom(room);
  auto log = std::make_shared<EventLog>();
  Slam slam(Config(), BackEndMode::kThreaded, RefinedPoseRecording::kOn, {log});
  EXPECT_EQ(StartInKeyFrameMap(file, room.frames[0].camera, DefaultVocabulary(), 10.0, &slam), "");
  slam.WaitForBackEnd();
  EXPECT_TRUE(slam.Localising());
  std::vector<int> expected{-1};
  for (const KeyFrame& keyframe : file.contents.keyframes) expected.push_back(keyframe.id);
  EXPECT_EQ(log->events, expected);
  EXPECT_GT(log->points, 100u);
  EXPECT_TRUE(slam.ProcessFrame(room.frames[kFrames - 1]).has_pose);  // localised at once
}

TEST(MapSession, AFileOfAnotherCameraIsRefusedAndTheRunGoesOn) {
  const test::RenderedSequence& room = test::SharedSequence("static_room", kFrames);
  const PinholeCamera& camera = *room.frames[0].camera;
  auto other = std::make_shared<const PinholeCamera>(
      camera.width(), camera.height(), camera.fx() * 1.1, camera.fy(), camera.cx(), camera.cy());
  Slam slam{Config()};
  const std::string why =
      StartInKeyFrameMap(MappedRoom(room), other, DefaultVocabulary(), 10.0, &slam);
  EXPECT_NE(why.find("camera"), std::string::npos) << why;
  EXPECT_FALSE(slam.Localising());
  EXPECT_TRUE(slam.ProcessFrame(room.frames[0]).has_pose);  // a map of its own from scratch
}

TEST(MapSession, AFileOfOtherOrbOrDepthNoiseSettingsIsRefused) {
  const test::RenderedSequence& room = test::SharedSequence("static_room", kFrames);
  const KeyFrameMapFile file = MappedRoom(room);
  ASSERT_TRUE(file.settings.has_value());
  EXPECT_EQ(file.settings->orb_levels, Config().features.num_levels);
  Config config;
  config.features.scale_factor = 1.3;
  Slam slam{config};
  EXPECT_EQ(StartInKeyFrameMap(file, room.frames[0].camera, DefaultVocabulary(), 10.0, &slam),
            "recorded with features.scale_factor 1.2 but this run uses 1.3");
  EXPECT_FALSE(slam.Localising());
  config = Config();
  config.depth_noise.sigma_d_constant_m = 2e-3;
  Slam other{config};
  EXPECT_EQ(StartInKeyFrameMap(file, room.frames[0].camera, DefaultVocabulary(), 10.0, &other),
            "recorded with depth_noise.sigma_d_constant_m 0.001 but this run uses 0.002");
}

}  // namespace
}  // namespace dslam
