// Odometry::StartInMap without the place recognition of loop_closing: a PlaceLookup that names a
// given keyframe, or none, on a short static_room sequence rendered in-process; with
// LoadedMapUse::kLocalisationOnly, the run that never leaves the loaded map.
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "dslam/tracking/odometry.h"
#include "support/rendered_sequence.h"
#include "support/textured_frame.h"

namespace dslam {
namespace {

constexpr char kScene[] = "static_room";
constexpr int kFrames = 40;

/// Names `ids` for every frame and counts the queries.
class FixedPlaces : public PlaceLookup {
 public:
  explicit FixedPlaces(std::vector<int> ids) : ids_(std::move(ids)) {}
  std::vector<int> Candidates(const Map&, const FrameFeatures&) override {
    ++queries;
    return ids_;
  }
  int queries = 0;

 private:
  std::vector<int> ids_;
};

/// The map of an odometry run over frames [0, frames).
Map MapOfFirstFrames(int frames) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  Odometry odometry{Config()};
  for (int i = 0; i < frames; ++i) odometry.ProcessFrame(room.frames[i]);
  return Map::FromContents(odometry.map().Contents());
}

TEST(OdometryLocalisation, AFrameIndexWhoseNextWouldOverflowIsRefused) {
  MapContents contents;
  KeyFrame keyframe;
  keyframe.id = 0;
  keyframe.frame_index = std::numeric_limits<int>::max();
  contents.keyframes.push_back(keyframe);
  Odometry odometry{Config()};
  const auto places = std::make_shared<FixedPlaces>(std::vector<int>{0});
  try {
    odometry.StartInMap(Map::FromContents(contents), places, 5.0);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "Odometry::StartInMap: keyframe frame_index 2147483647 is the largest int: the "
              "next frame's index would overflow");
  }
  EXPECT_FALSE(odometry.localising());
  contents.keyframes[0].frame_index = std::numeric_limits<int>::max() - 1;  // the next one fits
  odometry.StartInMap(Map::FromContents(contents), places, 5.0);
  EXPECT_TRUE(odometry.localising());
}

TEST(OdometryLocalisation, LocalisesAtTheNamedPlaceInTheLoadedWorld) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  Map map = MapOfFirstFrames(20);
  const int newest_frame = map.AllKeyFrames().back()->frame_index;
  Odometry odometry{Config()};
  auto places = std::make_shared<FixedPlaces>(std::vector<int>{0});
  odometry.StartInMap(std::move(map), places, 5.0);
  EXPECT_TRUE(odometry.localising());
  const FrameResult result = odometry.ProcessFrame(room.frames[25]);
  ASSERT_TRUE(result.has_pose);
  EXPECT_FALSE(odometry.localising());
  EXPECT_FALSE(result.has_previous_pose);       // a relocalised pose starts a new stretch
  EXPECT_GT(result.frame_index, newest_frame);  // indices go on after the loaded map's
  const Eigen::Isometry3d truth =
      room.groundtruth[0].T_world_camera.inverse() * room.groundtruth[25].T_world_camera;
  EXPECT_LT((result.T_world_camera.translation() - truth.translation()).norm(), 0.01);
  EXPECT_EQ(places->queries, 1);
  EXPECT_TRUE(odometry.ProcessFrame(room.frames[26]).has_pose);
  EXPECT_EQ(places->queries, 1);  // asked only while localising
}

// Keyframe and point ids stay unique for the life of an Odometry: starting in the loaded map
// again (the node does after every reset) must not hand out the ids of keyframes and points made
// in the loaded map since.
TEST(OdometryLocalisation, StartingInTheLoadedMapAgainNeverReusesIds) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  const Map loaded = MapOfFirstFrames(10);
  Odometry odometry{Config()};
  const auto places = std::make_shared<FixedPlaces>(std::vector<int>{0});
  odometry.StartInMap(Map::FromContents(loaded.Contents()), places, 5.0);
  for (int i = 10; i < 22; ++i) ASSERT_TRUE(odometry.ProcessFrame(room.frames[i]).has_pose) << i;
  const int next_keyframe = odometry.map().AllKeyFrames().back()->id + 1;
  const PointId next_point = odometry.map().next_point_id();
  ASSERT_GT(next_keyframe, loaded.AllKeyFrames().back()->id + 1);  // the run made keyframes
  odometry.StartInMap(Map::FromContents(loaded.Contents()), places, 5.0);
  const KeyFrame* made = nullptr;  // the first keyframe made after the second start
  for (int i = 22; i < kFrames && made == nullptr; ++i) {
    ASSERT_TRUE(odometry.ProcessFrame(room.frames[i]).has_pose) << i;
    for (const KeyFrame* keyframe : odometry.map().AllKeyFrames()) {
      if (keyframe->id > loaded.AllKeyFrames().back()->id) made = keyframe;
    }
  }
  ASSERT_NE(made, nullptr) << "no keyframe made after the second start";
  EXPECT_GE(made->id, next_keyframe);
  int new_points = 0;
  for (PointId id : made->points) {
    if (id < loaded.next_point_id()) continue;  // a loaded point
    ++new_points;
    EXPECT_GE(id, next_point);
  }
  EXPECT_GT(new_points, 0);
}

TEST(OdometryLocalisation, WithoutAPlaceTheTimeoutStartsANewWorld) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  Odometry odometry{Config()};
  odometry.StartInMap(MapOfFirstFrames(20), std::make_shared<FixedPlaces>(std::vector<int>{}),
                      0.25);
  // 30 Hz: frames 20-27 are within 0.25 s of frame 20, frame 28 is 0.267 s after it.
  for (int i = 20; i < 28; ++i) {
    const FrameResult result = odometry.ProcessFrame(room.frames[i]);
    EXPECT_FALSE(result.has_pose) << i;
    EXPECT_EQ(result.state, TrackingState::kLocalising) << i;
  }
  const FrameResult timed_out = odometry.ProcessFrame(room.frames[28]);
  EXPECT_TRUE(timed_out.reset);
  EXPECT_NE(timed_out.message.find("not localised"), std::string::npos) << timed_out.message;
  EXPECT_EQ(timed_out.state, TrackingState::kInitialised);
  EXPECT_TRUE(timed_out.has_pose);  // the first frame of a new world: the origin
  EXPECT_TRUE(timed_out.T_world_camera.isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_FALSE(odometry.localising());
  EXPECT_TRUE(odometry.ProcessFrame(room.frames[29]).has_pose);
}

TEST(OdometryLocalisation, LocalisationOnlyHasNoTimeout) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  Odometry odometry{Config()};
  odometry.StartInMap(MapOfFirstFrames(20), std::make_shared<FixedPlaces>(std::vector<int>{}), 0.25,
                      LoadedMapUse::kLocalisationOnly);
  EXPECT_TRUE(odometry.localisation_only());
  for (int i = 20; i < kFrames; ++i) {  // up to 0.63 s after frame 20
    const FrameResult result = odometry.ProcessFrame(room.frames[i]);
    EXPECT_FALSE(result.reset) << i;
    EXPECT_EQ(result.state, TrackingState::kLocalising) << i;
  }
  EXPECT_TRUE(odometry.localising());
}

// Localised at frame 20, then an unrelated view (random blocks at 2 m) for longer than
// tracking.lost_frames_before_reset frames, then the room again at frame 33.
TEST(OdometryLocalisation, LocalisationOnlyStaysLostWhereExtendingReinitialises) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  for (const LoadedMapUse use : {LoadedMapUse::kExtend, LoadedMapUse::kLocalisationOnly}) {
    const bool only = use == LoadedMapUse::kLocalisationOnly;
    Odometry odometry{Config()};
    odometry.StartInMap(MapOfFirstFrames(20), std::make_shared<FixedPlaces>(std::vector<int>{0}),
                        5.0, use);
    ASSERT_TRUE(odometry.ProcessFrame(room.frames[20]).has_pose) << only;
    int initialised = 0;
    for (int i = 21; i < 33; ++i) {
      RgbdFrame elsewhere = test::TexturedFrame(*room.frames[i].camera, 1, 2.0);
      elsewhere.stamp_s = room.frames[i].stamp_s;
      const FrameResult result = odometry.ProcessFrame(elsewhere);
      initialised += result.state == TrackingState::kInitialised ? 1 : 0;
      if (only) {
        EXPECT_EQ(result.state, TrackingState::kLost) << i;
      }
    }
    EXPECT_EQ(initialised > 0, !only);  // extending: a new map of the blocks
    if (!only) continue;
    const FrameResult back = odometry.ProcessFrame(room.frames[33]);
    ASSERT_TRUE(back.has_pose);
    const Eigen::Isometry3d truth =
        room.groundtruth[0].T_world_camera.inverse() * room.groundtruth[33].T_world_camera;
    EXPECT_LT((back.T_world_camera.translation() - truth.translation()).norm(), 0.01);
  }
}

// Localisation only with tracking.covisible_keyframes 0 (the default): once more temporary
// keyframes were made than the window's newest keyframes, the window must still hold loaded
// keyframes around the pose, so that tracking searches the loaded points there (before, the
// window was the newest temporary keyframes alone and tracking drifted on their new points).
TEST(OdometryLocalisation, LocalisationOnlyKeepsLoadedKeyFramesInTheWindow) {
  const test::RenderedSequence& room = test::SharedSequence(kScene, kFrames);
  Config config;
  config.tracking.window_keyframes = 3;
  config.tracking.keyframe_max_interval = 2;  // a temporary keyframe at least every 2 frames
  ASSERT_EQ(config.tracking.covisible_keyframes, 0);
  Odometry odometry{config};
  Map loaded = MapOfFirstFrames(kFrames);
  const int loaded_end = loaded.AllKeyFrames().back()->id + 1;
  odometry.StartInMap(std::move(loaded), std::make_shared<FixedPlaces>(std::vector<int>{0}), 5.0,
                      LoadedMapUse::kLocalisationOnly);
  int temporary = 0;
  for (int i = 2; i < kFrames; ++i) {
    const FrameResult result = odometry.ProcessFrame(room.frames[i]);
    ASSERT_TRUE(result.has_pose) << i;
    temporary += result.keyframe ? 1 : 0;
    if (temporary <= config.tracking.window_keyframes) continue;
    int loaded_in_window = 0;
    for (const KeyFrame& keyframe : odometry.map().window()) {
      loaded_in_window += keyframe.id < loaded_end ? 1 : 0;
    }
    EXPECT_GE(loaded_in_window, 1) << "frame " << i << ": no loaded keyframe in the window";
  }
  EXPECT_GT(temporary, 2 * config.tracking.window_keyframes);
}

TEST(OdometryLocalisation, StartInMapRefusesWhatCannotLocalise) {
  Odometry odometry{Config()};
  EXPECT_THROW(odometry.StartInMap(Map(), nullptr, 1.0), std::invalid_argument);
  auto places = std::make_shared<FixedPlaces>(std::vector<int>{});
  EXPECT_THROW(odometry.StartInMap(Map(), places, 0.0), std::invalid_argument);
  Config no_relocalisation;
  no_relocalisation.tracking.relocalisation = false;
  Odometry without{no_relocalisation};
  EXPECT_THROW(without.StartInMap(Map(), places, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace dslam
