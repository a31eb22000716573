// ApplyStaticLabels: how the front end's labels turn into marks on map points.
#include <gtest/gtest.h>

#include "dslam/tracking/front_end_static_points.h"

namespace dslam {
namespace {

// One map point matched to feature 0, labelled `label` by a front end that chose a static
// component.
struct OnePoint {
  Map map;
  PointId id = -1;
  std::vector<PointMatch> matches;
  FrontEndStaticPoints front_end;

  explicit OnePoint(bool candidate) {
    MapPoint point;
    point.candidate = candidate;
    id = map.AddPoint(point);
    matches = {{id, 0}};
    front_end.ran = true;
    front_end.graph_match = {0};
    front_end.result.static_component = 0;
    front_end.result.labels = {PointLabel::kStatic};
  }
  // Applies `label` in frame `frame`; returns whether the match was kept out of the pose.
  bool Apply(PointLabel label, int frame, const LabelRules& rules) {
    front_end.result.labels[0] = label;
    return ApplyStaticLabels(front_end, matches, rules, frame, &map)[0];
  }
  const MapPoint& point() { return *map.Find(id); }
};

TEST(StaticLabels, CandidateVerifiedOnlyWhenStaticLateEnough) {
  OnePoint p(true);
  const LabelRules rules{3, 6, 15};
  EXPECT_FALSE(p.Apply(PointLabel::kStatic, 5, rules));
  EXPECT_TRUE(p.point().candidate);  // 5 frames after creation (frame 0): too early
  p.Apply(PointLabel::kStatic, 6, rules);
  EXPECT_FALSE(p.point().candidate);
  EXPECT_TRUE(p.point().marked);
}

TEST(StaticLabels, DynamicUnmarksAndIsolatedOnlyAfterARun) {
  OnePoint p(false);
  const LabelRules rules{3, 6, 15};
  EXPECT_TRUE(p.Apply(PointLabel::kIsolated, 1, rules));
  EXPECT_TRUE(p.Apply(PointLabel::kIsolated, 2, rules));
  EXPECT_TRUE(p.point().marked);
  p.Apply(PointLabel::kIsolated, 3, rules);
  EXPECT_FALSE(p.point().marked);

  OnePoint q(false);
  EXPECT_TRUE(q.Apply(PointLabel::kDynamic, 1, rules));
  EXPECT_FALSE(q.point().marked);
}

TEST(StaticLabels, RemarkedAfterAsManyStaticFramesAsItWasDynamic) {
  OnePoint p(false);
  const LabelRules rules{3, 6, 15};
  for (int f = 1; f <= 4; ++f) p.Apply(PointLabel::kDynamic, f, rules);
  for (int f = 5; f <= 7; ++f) {
    p.Apply(PointLabel::kStatic, f, rules);
    EXPECT_FALSE(p.point().marked) << "frame " << f;
  }
  p.Apply(PointLabel::kStatic, 8, rules);  // 4th static frame in a row
  EXPECT_TRUE(p.point().marked);

  // Dynamic once: back after one static frame. An isolated frame breaks the run.
  OnePoint q(false);
  q.Apply(PointLabel::kDynamic, 1, rules);
  q.Apply(PointLabel::kStatic, 2, rules);
  EXPECT_TRUE(q.point().marked);
  OnePoint r(false);
  r.Apply(PointLabel::kDynamic, 1, rules);
  r.Apply(PointLabel::kDynamic, 2, rules);
  r.Apply(PointLabel::kStatic, 3, rules);
  r.Apply(PointLabel::kIsolated, 4, rules);
  r.Apply(PointLabel::kStatic, 5, rules);
  EXPECT_FALSE(r.point().marked);
  r.Apply(PointLabel::kStatic, 6, rules);
  EXPECT_TRUE(r.point().marked);
}

TEST(StaticLabels, RemarkWaitIsCappedAndOneMeansAtOnce) {
  OnePoint p(false);
  const LabelRules capped{3, 6, 5};
  for (int f = 1; f <= 40; ++f) p.Apply(PointLabel::kDynamic, f, capped);
  for (int f = 41; f <= 44; ++f) p.Apply(PointLabel::kStatic, f, capped);
  EXPECT_FALSE(p.point().marked);
  p.Apply(PointLabel::kStatic, 45, capped);
  EXPECT_TRUE(p.point().marked);

  OnePoint q(false);
  const LabelRules at_once{3, 6, 1};
  for (int f = 1; f <= 10; ++f) q.Apply(PointLabel::kDynamic, f, at_once);
  q.Apply(PointLabel::kStatic, 11, at_once);
  EXPECT_TRUE(q.point().marked);
}

TEST(StaticLabels, NothingChangesWithoutAStaticComponent) {
  OnePoint p(false);
  p.front_end.result.static_component = -1;
  EXPECT_FALSE(p.Apply(PointLabel::kDynamic, 1, LabelRules{}));
  EXPECT_TRUE(p.point().marked);
}

}  // namespace
}  // namespace dslam
