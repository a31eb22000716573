// The keyframe map's pose graph for a loop (loop_correction.h): its nodes and edges, and that
// solving it takes a drifted ring of keyframes back onto the truth.
#include "dslam/loop_closing/loop_correction.h"

#include <cmath>

#include <gtest/gtest.h>

namespace dslam {
namespace {

constexpr int kKeyFrames = 24;

// [m] T_world_camera of keyframe k on a circle of radius 1.5 m, looking outwards.
Eigen::Isometry3d TruePose(int k) {
  const double a = 2.0 * M_PI * k / kKeyFrames;
  Eigen::Isometry3d T(Eigen::AngleAxisd(-a, Eigen::Vector3d::UnitY()));
  T.translation() = Eigen::Vector3d(1.5 * std::cos(a), 0.0, 1.5 * std::sin(a));
  return T;
}

// Keyframes along the ring with drift growing to 0.2 m and 4 deg at the last one; keyframe k
// lists points 50k .. 50k+149 (neighbours share 100, the next but one 50), and keyframes 1 and 5
// list 100 more points both (a covisibility edge that is not a spanning one).
Map DriftedRing() {
  Map map;
  for (int i = 0; i < 50 * kKeyFrames + 200; ++i) map.AddPoint(MapPoint());
  for (int k = 0; k < kKeyFrames; ++k) {
    const double drift = static_cast<double>(k) / (kKeyFrames - 1);
    KeyFrame keyframe;
    keyframe.frame_index = 10 * k;
    keyframe.T_world_camera =
        Eigen::Translation3d(0.0, 0.2 * drift, 0.0) *
        Eigen::AngleAxisd(4.0 * M_PI / 180.0 * drift, Eigen::Vector3d::UnitY()) * TruePose(k);
    keyframe.measurements.T_camera_world = keyframe.T_world_camera.inverse();
    for (int i = 50 * k; i < 50 * k + 150; ++i) keyframe.points.push_back(i);
    if (k == 1 || k == 5) {  // the 100 points after the ring's
      for (int i = 50 * kKeyFrames + 100; i < 50 * kKeyFrames + 200; ++i) {
        keyframe.points.push_back(i);
      }
    }
    map.AddKeyFrame(keyframe, {8, 0, 1000});
  }
  return map;
}

TEST(LoopCorrection, GraphHasEveryKeyFrameTheSpanningTreeCovisibilityAndTheLoop) {
  const Map map = DriftedRing();
  const Eigen::Isometry3d T_0_last = TruePose(0).inverse() * TruePose(kKeyFrames - 1);
  const PoseGraph graph = BuildLoopPoseGraph(map, {{0, kKeyFrames - 1, T_0_last}});
  ASSERT_EQ(graph.nodes.size(), static_cast<size_t>(kKeyFrames));
  EXPECT_TRUE(graph.nodes.at(0).fixed);
  EXPECT_FALSE(graph.nodes.at(1).fixed);
  int spanning = 0, covisibility = 0, loops = 0;
  for (const PoseGraphEdge& edge : graph.edges) {
    spanning += edge.kind == PoseGraphEdgeKind::kSpanningTree;
    loops += edge.kind == PoseGraphEdgeKind::kLoop;
    if (edge.kind == PoseGraphEdgeKind::kCovisibility) {
      ++covisibility;
      EXPECT_EQ(edge.id_a, 1);
      EXPECT_EQ(edge.id_b, 5);
    }
  }
  EXPECT_EQ(spanning, kKeyFrames - 1);
  EXPECT_EQ(covisibility, 1);  // neighbours share 100 too, but they have their spanning edge
  EXPECT_EQ(loops, 1);
  EXPECT_THROW(BuildLoopPoseGraph(map, {{0, 99, T_0_last}}), std::invalid_argument);
  // An older loop whose keyframe was erased is left out; the new one must be in the map.
  const PoseGraph two = BuildLoopPoseGraph(map, {{0, 99, T_0_last}, {0, kKeyFrames - 1, T_0_last}});
  EXPECT_EQ(two.edges.size(), graph.edges.size());
  const PoseGraph both = BuildLoopPoseGraph(map, {{1, 20, T_0_last}, {0, kKeyFrames - 1, T_0_last}});
  EXPECT_EQ(both.edges.size(), graph.edges.size() + 1);
}

TEST(LoopCorrection, SolvingTheGraphTakesTheDriftedRingBackOntoTheTruth) {
  const Map map = DriftedRing();
  const int last = kKeyFrames - 1;
  const Eigen::Isometry3d T_0_last = TruePose(0).inverse() * TruePose(last);
  const std::map<int, Eigen::Isometry3d> corrected =
      CorrectedKeyFramePoses(BuildLoopPoseGraph(map, {{0, last, T_0_last}}));
  ASSERT_EQ(corrected.size(), static_cast<size_t>(kKeyFrames));
  double worst_before = 0.0, worst_after = 0.0;
  Map copy = map;
  for (int k = 0; k < kKeyFrames; ++k) {
    worst_before = std::max(worst_before, (copy.FindKeyFrame(k)->T_world_camera.translation() -
                                           TruePose(k).translation()).norm());
    worst_after = std::max(
        worst_after, (corrected.at(k).translation() - TruePose(k).translation()).norm());
  }
  EXPECT_GT(worst_before, 0.2);
  EXPECT_LT(worst_after, 0.25 * worst_before);  // measured 0.044 against 0.226 m: the odometry
  // edges carry the drift, so the solve spreads the loop's error over the ring, not removes it
  const Eigen::Isometry3d loop_after = corrected.at(0).inverse() * corrected.at(last);
  EXPECT_LT((loop_after.translation() - T_0_last.translation()).norm(), 0.01);
}

}  // namespace
}  // namespace dslam
