// The loop neighbourhood's corrected initial guesses (ORB-SLAM2's CorrectLoop before the graph):
// neighbours keep their poses relative to the current keyframe, and on the drifting ring the
// corrected guesses start the solve nearer the answer.
#include "dslam/loop_closing/neighbourhood_correction.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "loop_closing/ring_graph.h"

namespace dslam {
namespace {

TEST(NeighbourhoodCorrection, NeighboursMoveRigidlyWithTheCurrentKeyFrame) {
  const test::Ring ring = test::MakeRing(test::DriftingRingOptions());
  const Eigen::Isometry3d T_world_current_corrected = ring.T_world_camera_true[39];
  const std::map<int, Eigen::Isometry3d> corrected =
      CorrectLoopNeighbourhood(ring.graph, 39, T_world_current_corrected, {36, 37, 38, 39});
  ASSERT_EQ(corrected.size(), 4u);
  EXPECT_TRUE(corrected.at(39).isApprox(T_world_current_corrected, 0));
  const Eigen::Isometry3d& T_world_current = ring.graph.nodes.at(39).T_world_camera;
  for (const int id : {36, 37, 38}) {
    const Eigen::Isometry3d T_current_neighbour =
        T_world_current.inverse() * ring.graph.nodes.at(id).T_world_camera;
    EXPECT_TRUE((T_world_current_corrected.inverse() * corrected.at(id))
                    .isApprox(T_current_neighbour, 1e-12))
        << "keyframe " << id;
  }
  EXPECT_THROW(CorrectLoopNeighbourhood(ring.graph, 39, T_world_current_corrected, {38, 41}),
               std::invalid_argument);
  EXPECT_THROW(CorrectLoopNeighbourhood(ring.graph, 41, T_world_current_corrected, {38}),
               std::invalid_argument);
}

TEST(NeighbourhoodCorrection, SetInitialGuessesChangesNothingOnAMissingNode) {
  test::Ring ring = test::MakeRing(test::DriftingRingOptions());
  const PoseGraph before = ring.graph;
  const Eigen::Isometry3d T = test::Motion({0.1, 0, 0}, {1, 1, 1});
  EXPECT_THROW(SetInitialGuesses({{5, T}, {99, T}}, &ring.graph), std::invalid_argument);
  EXPECT_TRUE(ring.graph.nodes.at(5).T_world_camera.isApprox(before.nodes.at(5).T_world_camera, 0));
  SetInitialGuesses({{5, T}}, &ring.graph);
  EXPECT_TRUE(ring.graph.nodes.at(5).T_world_camera.isApprox(T, 0));
  EXPECT_EQ(ring.graph.nodes.at(5).fixed, before.nodes.at(5).fixed);
}

TEST(NeighbourhoodCorrection, CorrectedGuessesStartTheSolveNearerTheAnswer) {
  const test::Ring ring = test::MakeRing(test::DriftingRingOptions());
  PoseGraph graph = ring.graph;  // edges measured from the poses before the correction
  const std::vector<int> neighbourhood = {35, 36, 37, 38, 39};
  SetInitialGuesses(
      CorrectLoopNeighbourhood(graph, 39, ring.T_world_camera_true[39], neighbourhood), &graph);
  const PoseGraphResult plain = OptimisePoseGraph(ring.graph);
  const PoseGraphResult guessed = OptimisePoseGraph(graph);
  ASSERT_TRUE(guessed.success);
  // The loop edge agrees with the corrected guesses: the cost is then in the five edges into the
  // neighbourhood (34 -> 35), less than the loop edge's before.
  EXPECT_LT(guessed.initial_cost, plain.initial_cost);
  // The same minimum, to Ceres' default tolerances.
  EXPECT_NEAR(guessed.final_cost, plain.final_cost, 1e-3 * plain.final_cost);
  for (const auto& [id, T] : plain.T_world_camera) {
    const test::PoseError difference = test::ErrorOf(guessed.T_world_camera.at(id), T);
    EXPECT_LT(difference.translation_m, 1e-3) << "keyframe " << id;
    EXPECT_LT(difference.rotation_rad, 1e-4) << "keyframe " << id;
  }
}

}  // namespace
}  // namespace dslam
