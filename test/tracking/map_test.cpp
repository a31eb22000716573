#include <algorithm>

#include <gtest/gtest.h>

#include "dslam/tracking/map.h"

namespace dslam {
namespace {

TEST(Map, AddFindEraseAssignsUniqueIds) {
  Map map;
  const PointId a = map.AddPoint(MapPoint());
  const PointId b = map.AddPoint(MapPoint());
  EXPECT_NE(a, b);
  ASSERT_NE(map.Find(a), nullptr);
  EXPECT_EQ(map.Find(a)->id, a);
  map.Erase(a);
  EXPECT_EQ(map.Find(a), nullptr);
  EXPECT_EQ(map.size(), 1u);
}

TEST(Map, KeyFrameWindowAndLocalPoints) {
  Map map;
  std::vector<PointId> ids;
  for (int i = 0; i < 6; ++i) ids.push_back(map.AddPoint(MapPoint()));
  for (int k = 0; k < 3; ++k) {
    KeyFrame kf;
    kf.points = {ids[2 * k], ids[2 * k + 1]};
    map.AddKeyFrame(kf, KeyFrameMapLimits::Newest(2));
  }
  ASSERT_EQ(map.window().size(), 2u);
  EXPECT_EQ(map.window().front().id, 1);
  auto local = map.LocalPoints({ids[0], ids[2]});
  std::sort(local.begin(), local.end());
  EXPECT_EQ(local, (std::vector<PointId>{ids[0], ids[2], ids[3], ids[4], ids[5]}));
  map.Erase(ids[4]);
  EXPECT_EQ(map.LocalPoints({}).size(), 3u);
}

// The recently seen verified static points come from the points added or seen (MarkSeen), not a
// walk over the map: a point not seen since the bound leaves the list, and comes back when seen.
TEST(Map, LocalPointsFindVerifiedStaticPointsSeenSinceTheBound) {
  Map map;
  MapPoint verified;
  verified.marked = true;
  verified.candidate = false;
  std::vector<PointId> ids;
  for (int i = 0; i < 4; ++i) {
    verified.last_seen_frame = 10 * i;  // 0, 10, 20, 30
    ids.push_back(map.AddPoint(verified));
  }
  map.Find(ids[3])->candidate = true;  // not verified: never a recently seen static point
  const auto sorted = [](std::vector<PointId> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  EXPECT_EQ(sorted(map.LocalPoints({}, 5)), (std::vector<PointId>{ids[1], ids[2]}));
  EXPECT_EQ(sorted(map.LocalPoints({}, 15)), (std::vector<PointId>{ids[2]}));
  map.MarkSeen(map.Find(ids[0]), 40);  // seen again after it left the list
  EXPECT_EQ(map.Find(ids[0])->last_seen_frame, 40);
  EXPECT_EQ(sorted(map.LocalPoints({}, 35)), (std::vector<PointId>{ids[0]}));
  map.Erase(ids[0]);
  EXPECT_TRUE(map.LocalPoints({}, 35).empty());
  map.Clear();
  EXPECT_TRUE(map.LocalPoints({}, 0).empty());
}

TEST(Map, CullRemovesStaleAndUnreliablePoints) {
  Map map;
  MapPoint stale;
  stale.last_seen_frame = 3;
  MapPoint recent;
  recent.last_seen_frame = 20;
  MapPoint unreliable;
  unreliable.last_seen_frame = 20;
  unreliable.times_visible = 10;
  unreliable.times_found = 1;
  MapPoint in_window;
  in_window.last_seen_frame = 1;
  const PointId s = map.AddPoint(stale), r = map.AddPoint(recent);
  const PointId u = map.AddPoint(unreliable), w = map.AddPoint(in_window);
  KeyFrame kf;
  kf.points = {w};
  map.AddKeyFrame(kf, KeyFrameMapLimits::Newest(5));
  EXPECT_EQ(map.Cull(10, 0.25, 5), 2);
  EXPECT_EQ(map.Find(s), nullptr);
  EXPECT_EQ(map.Find(u), nullptr);
  EXPECT_NE(map.Find(r), nullptr);
  EXPECT_NE(map.Find(w), nullptr);
}

TEST(Map, VerifiedStaticPointsOutsideTheWindowAreKeptAndSearched) {
  Map map;
  MapPoint hidden_static;  // verified static, last seen in frame 8, in no window keyframe
  hidden_static.last_seen_frame = 8;
  MapPoint hidden_candidate = hidden_static;
  hidden_candidate.candidate = true;
  MapPoint hidden_dynamic = hidden_static;
  hidden_dynamic.marked = false;
  MapPoint long_gone = hidden_static;
  long_gone.last_seen_frame = 2;
  const PointId s = map.AddPoint(hidden_static), c = map.AddPoint(hidden_candidate);
  const PointId d = map.AddPoint(hidden_dynamic), g = map.AddPoint(long_gone);
  EXPECT_TRUE(map.LocalPoints({}).empty());  // no keyframe refers to them
  const std::vector<PointId> local = map.LocalPoints({}, 5);
  ASSERT_EQ(local.size(), 1u);
  EXPECT_EQ(local[0], s);
  // Window starts at frame 10; verified static points seen since frame 5 survive.
  EXPECT_EQ(map.Cull(10, 0.25, 5, 5), 3);
  EXPECT_NE(map.Find(s), nullptr);
  EXPECT_EQ(map.Find(c), nullptr);
  EXPECT_EQ(map.Find(d), nullptr);
  EXPECT_EQ(map.Find(g), nullptr);
}

// The label transitions both static point determinations use (front end: Unmark(0) per dynamic
// frame, LookedStatic per static frame; back end: Unmark(remark_frames)).
TEST(MapPointLabels, UnmarkCountsTheEvidenceAndLookedStaticMarksAgain) {
  constexpr int kRemarkFrames = 5;
  MapPoint point;
  point.candidate = true;
  point.static_streak = 3;
  point.Unmark(0);  // the front end: one dynamic frame
  EXPECT_FALSE(point.marked);
  EXPECT_FALSE(point.candidate);
  EXPECT_EQ(point.static_streak, 0);
  EXPECT_EQ(point.dynamic_frames, 1);
  point.LookedStatic(kRemarkFrames);  // one bad frame: back after one static frame
  EXPECT_TRUE(point.marked);
  EXPECT_EQ(point.dynamic_frames, 0);

  point.Unmark(kRemarkFrames);  // the window: at least remark_frames of evidence at once
  EXPECT_EQ(point.dynamic_frames, kRemarkFrames);
  point.Unmark(0);
  point.Unmark(0);
  EXPECT_EQ(point.dynamic_frames, kRemarkFrames + 2);
  for (int frame = 1; frame < kRemarkFrames; ++frame) {
    point.LookedStatic(kRemarkFrames);
    EXPECT_FALSE(point.marked) << "static frame " << frame;
  }
  point.LookedStatic(kRemarkFrames);  // min(remark_frames, dynamic_frames) static frames
  EXPECT_TRUE(point.marked);
  point.LookedStatic(kRemarkFrames);  // a marked point stays as it is
  EXPECT_TRUE(point.marked);
  EXPECT_EQ(point.static_streak, kRemarkFrames);
}

}  // namespace
}  // namespace dslam
