// Known-answer tests of the pose graph (OptimisePoseGraph) on rings of keyframes
// (loop_closing/ring_graph.h): drift removed by a loop edge, truth left alone, fixed nodes held,
// bad input rejected.
#include "dslam/loop_closing/pose_graph.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "loop_closing/ring_graph.h"
#include "support/thrown_message.h"

namespace dslam {
namespace {

constexpr double kDegree = M_PI / 180.0;

// The message of the std::invalid_argument that `optimise` throws ("" when none).
template <typename F>
std::string InvalidArgumentMessage(F optimise) {
  return test::ThrownMessage<std::invalid_argument>(optimise);
}

TEST(PoseGraph, LoopEdgeRemovesAccumulatedDrift) {
  const test::Ring ring = test::MakeRing(test::DriftingRingOptions());
  const test::PoseError before = test::MaxError(test::NodePoses(ring.graph), ring);
  // The fixture: the chained odometry ends 0.3 m and 5 deg off.
  const test::PoseError end =
      test::ErrorOf(ring.graph.nodes.at(39).T_world_camera, ring.T_world_camera_true[39]);
  EXPECT_NEAR(end.translation_m, 0.3, 0.05);
  EXPECT_NEAR(end.rotation_rad, 5.0 * kDegree, 0.5 * kDegree);

  const PoseGraphResult result = OptimisePoseGraph(ring.graph);
  ASSERT_TRUE(result.success);
  ASSERT_EQ(result.T_world_camera.size(), 40u);
  const test::PoseError after = test::MaxError(result.T_world_camera, ring);
  EXPECT_LT(after.translation_m, 0.03);
  EXPECT_LT(after.rotation_rad, 0.5 * kDegree);
  EXPECT_LT(after.translation_m, before.translation_m / 10);
  EXPECT_LT(result.final_cost, result.initial_cost / 20);
  EXPECT_GT(result.iterations, 0);
}

TEST(PoseGraph, PerfectMeasurementsLeaveTheTruth) {
  test::RingOptions options;
  options.noise_translation_m = 0.0;
  options.noise_rotation_rad = 0.0;
  const test::Ring ring = test::MakeRing(options);
  const PoseGraphResult result = OptimisePoseGraph(ring.graph);
  ASSERT_TRUE(result.success);
  EXPECT_LT(result.initial_cost, 1e-18);
  EXPECT_LT(result.final_cost, 1e-18);
  const test::PoseError after = test::MaxError(result.T_world_camera, ring);
  EXPECT_LT(after.translation_m, 1e-9);
  EXPECT_LT(after.rotation_rad, 1e-9);
}

TEST(PoseGraph, FixedNodesDoNotMove) {
  test::Ring ring = test::MakeRing(test::DriftingRingOptions());
  ring.graph.nodes.at(20).fixed = true;  // besides node 0
  const PoseGraphResult result = OptimisePoseGraph(ring.graph);
  ASSERT_TRUE(result.success);
  for (const int id : {0, 20}) {
    EXPECT_TRUE(result.T_world_camera.at(id).isApprox(ring.graph.nodes.at(id).T_world_camera, 0))
        << "keyframe " << id;
  }
  // The free nodes moved: node 39 ends far nearer its true pose than the chained guess.
  EXPECT_LT(test::ErrorOf(result.T_world_camera.at(39), ring.T_world_camera_true[39]).translation_m,
            0.1);
}

TEST(PoseGraph, NodeWithoutEdgesKeepsItsPose) {
  test::Ring ring = test::MakeRing(test::DriftingRingOptions());
  const Eigen::Isometry3d T_world_lonely = test::Motion({0.1, 0.2, 0.3}, {1, 2, 3});
  ring.graph.nodes[100] = {T_world_lonely, false};
  const PoseGraphResult result = OptimisePoseGraph(ring.graph);
  EXPECT_TRUE(result.T_world_camera.at(100).isApprox(T_world_lonely, 1e-12));
}

TEST(PoseGraph, BadGraphsThrowNamingTheNode) {
  test::Ring ring = test::MakeRing(test::RingOptions());
  PoseGraph missing = ring.graph;
  missing.edges[5].id_b = 99;
  EXPECT_NE(InvalidArgumentMessage([&] { OptimisePoseGraph(missing); }).find("keyframe 99"),
            std::string::npos);
  PoseGraph unfixed = ring.graph;
  unfixed.nodes.at(0).fixed = false;
  EXPECT_NE(InvalidArgumentMessage([&] { OptimisePoseGraph(unfixed); }).find("no node is fixed"),
            std::string::npos);
  PoseGraph self = ring.graph;
  self.edges[3].id_b = self.edges[3].id_a;
  EXPECT_NE(InvalidArgumentMessage([&] { OptimisePoseGraph(self); }).find("keyframe 3"),
            std::string::npos);
  PoseGraph singular = ring.graph;
  singular.edges[7].information.setZero();
  EXPECT_NE(InvalidArgumentMessage([&] { OptimisePoseGraph(singular); }).find("edge 7 -> 8"),
            std::string::npos);
  PoseGraphOptions options;
  options.num_threads = 0;
  EXPECT_NE(InvalidArgumentMessage([&] { OptimisePoseGraph(ring.graph, options); }), "");
  EXPECT_THROW(PoseGraphEdgeInformation(0.0, 0.01), std::invalid_argument);
  EXPECT_THROW(MakePoseGraphEdge(ring.graph, 0, 77, PoseGraphEdgeKind::kLoop,
                                 PoseGraphInformation::Identity()),
               std::invalid_argument);
}

TEST(PoseGraph, ResidualIsTheRelativePoseErrorInFrameA) {
  PoseGraphEdge edge;  // measured T_a_b = identity, information identity
  const Eigen::Isometry3d T_world_a = test::Motion({0, 0, M_PI / 2}, {1, 0, 0});
  // b rotated 0.1 rad about a's x axis and 0.2 m along a's y axis.
  const Eigen::Isometry3d T_world_b = T_world_a * test::Motion({0.1, 0, 0}, {0, 0.2, 0});
  Eigen::Matrix<double, 6, 1> expected;
  expected << 0.1, 0, 0, 0, 0.2, 0;
  EXPECT_TRUE(PoseGraphResidual(edge, T_world_a, T_world_b).isApprox(expected, 1e-12));
  edge.information = PoseGraphEdgeInformation(0.01, 0.05);  // whitened: / sigma
  expected << 2.0, 0, 0, 0, 20.0, 0;
  EXPECT_TRUE(PoseGraphResidual(edge, T_world_a, T_world_b).isApprox(expected, 1e-12));
  edge = MakePoseGraphEdge(PoseGraph{{{1, {T_world_a, true}}, {2, {T_world_b, false}}}, {}}, 1, 2,
                           PoseGraphEdgeKind::kCovisibility, PoseGraphInformation::Identity());
  EXPECT_LT(PoseGraphResidual(edge, T_world_a, T_world_b).norm(), 1e-12);
}

TEST(PoseGraph, SameResultOnEveryRun) {
  const test::Ring ring = test::MakeRing(test::DriftingRingOptions());
  const PoseGraphResult first = OptimisePoseGraph(ring.graph);
  const PoseGraphResult second = OptimisePoseGraph(ring.graph);
  EXPECT_EQ(first.final_cost, second.final_cost);
  for (const auto& [id, T] : first.T_world_camera) {
    EXPECT_TRUE(T.isApprox(second.T_world_camera.at(id), 0)) << "keyframe " << id;
  }
}

}  // namespace
}  // namespace dslam
