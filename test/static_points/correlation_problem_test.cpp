#include "dslam/static_points/correlation_problem.h"

#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "dslam/synth/point_scene.h"
#include "static_points/culling_score.h"

namespace dslam {
namespace {

using synth::MakePointScene;
using synth::PointScene;
using synth::PointSceneOptions;
using testing_util::CullingScore;
using testing_util::ScoreCulling;

struct Scores {
  CullingScore least_squares;  // default options
  CullingScore strict;         // least squares, every measurement must stay an inlier
  CullingScore direct;
};

Scores RunCulling(const PointSceneOptions& o, const char* name) {
  const PointScene scene = MakePointScene(o);
  const auto edges = BuildDelaunayGraph(scene.input.points_world);
  const CullingResult ls = CullInconsistentEdges(scene.input, edges, CullingOptions());
  CullingOptions strict_options;
  strict_options.min_inlier_fraction = 1.0;
  const CullingResult strict = CullInconsistentEdges(scene.input, edges, strict_options);
  const CullingResult direct = DirectEdgeTest(scene.input, edges, 0.99);
  Scores s{ScoreCulling(edges, ls.edge_kept, scene.is_dynamic),
           ScoreCulling(edges, strict.edge_kept, scene.is_dynamic),
           ScoreCulling(edges, direct.edge_kept, scene.is_dynamic)};
  std::printf(
      "[%s] edges %d boundary %d | LS rounds %d culled %d recall %.3f precision %.3f |"
      " LS strict culled %d recall %.3f precision %.3f |"
      " direct culled %d recall %.3f precision %.3f\n",
      name, s.least_squares.edges, s.least_squares.boundary, ls.rounds, s.least_squares.culled,
      s.least_squares.Recall(), s.least_squares.Precision(), s.strict.culled, s.strict.Recall(),
      s.strict.Precision(), s.direct.culled, s.direct.Recall(), s.direct.Precision());
  return s;
}

TEST(ChiSquareQuantile, MatchesTables) {
  EXPECT_NEAR(ChiSquareQuantile(3, 0.95), 7.815, 0.06);
  EXPECT_NEAR(ChiSquareQuantile(3, 0.99), 11.345, 0.05);
  EXPECT_NEAR(ChiSquareQuantile(21, 0.99), 38.932, 0.1);
  EXPECT_NEAR(ChiSquareQuantile(6, 0.95), 12.592, 0.05);
}

// Exact data: no edge is culled and the optimised points equal the truth.
TEST(CullInconsistentEdges, NoiseFreeStaticSceneKeepsEverything) {
  CorrelationInput in;
  in.points_world = {{0, 0, 2}, {1, 0, 3}, {0, 1, 4}, {1, 1, 2.5}, {0.5, 0.5, 3}};
  for (int k = 0; k < 3; ++k) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(0.1 * k, Eigen::Vector3d::UnitY()).toRotationMatrix();
    T.translation() = Eigen::Vector3d(0.1 * k, 0, 0);
    in.T_camera_world.push_back(T);
    for (int i = 0; i < 5; ++i) {
      in.observations.push_back({i, k, T * in.points_world[i], Eigen::Matrix3d::Identity() * 1e-4});
    }
  }
  const auto edges = BuildDelaunayGraph(in.points_world);
  const CullingResult r = CullInconsistentEdges(in, edges, CullingOptions());
  EXPECT_EQ(r.rounds, 1);
  EXPECT_EQ(r.measurements, 3 * static_cast<int>(edges.size()));
  for (size_t e = 0; e < edges.size(); ++e) {
    EXPECT_TRUE(r.edge_kept[e]);
    EXPECT_EQ(r.edge_inliers[e], 3);
    EXPECT_LT(r.edge_max_chi2[e], 1e-12);
  }
  for (int i = 0; i < 5; ++i) EXPECT_LT((r.points_world[i] - in.points_world[i]).norm(), 1e-9);
}

TEST(CullInconsistentEdges, RejectsBadIndices) {
  CorrelationInput in;
  in.points_world = {{0, 0, 2}, {1, 0, 3}};
  in.T_camera_world = {Eigen::Isometry3d::Identity()};
  in.observations.push_back({0, 1, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity()});
  EXPECT_THROW(CullInconsistentEdges(in, {{0, 1}}, CullingOptions()), std::invalid_argument);
}

// No motion: with 99% thresholds, fewer than 3% of the edges may be culled.
TEST(CullInconsistentEdges, StaticSceneCullsAlmostNothing) {
  for (int frames : {2, 5}) {
    PointSceneOptions o;
    o.frames = frames;
    o.cluster_motion.setZero();
    const Scores s = RunCulling(o, frames == 2 ? "static 2f" : "static 5f");
    EXPECT_LT(s.least_squares.CulledFraction(), 0.03) << frames;
    EXPECT_LT(s.direct.CulledFraction(), 0.03) << frames;
  }
}

TEST(CullInconsistentEdges, TenCentimetreMoveCutsTheBoundary) {
  for (int frames : {2, 5}) {
    PointSceneOptions o;
    o.frames = frames;
    const Scores s = RunCulling(o, frames == 2 ? "move 2f" : "move 5f");
    EXPECT_GE(s.least_squares.Recall(), 0.95) << frames;
    EXPECT_GE(s.least_squares.Precision(), 0.6) << frames;
    EXPECT_GE(s.direct.Recall(), 0.95) << frames;
    EXPECT_GE(s.direct.Precision(), 0.8) << frames;
  }
}

// Algorithm 1's edge rule (cut only when every measurement is an outlier) lets an object in
// steady motion keep edges through the frames in the middle of the window: the least-squares
// fit sits at the mean layout. The default rule (every measurement must stay an inlier) cuts
// them all.
TEST(CullInconsistentEdges, PaperEdgeRuleMissesSteadyMotionOverManyFrames) {
  PointSceneOptions o;
  o.frames = 5;
  const PointScene scene = MakePointScene(o);
  const auto edges = BuildDelaunayGraph(scene.input.points_world);
  CullingOptions paper;
  paper.min_inlier_fraction = 0.0;
  const CullingScore literal = ScoreCulling(
      edges, CullInconsistentEdges(scene.input, edges, paper).edge_kept, scene.is_dynamic);
  const CullingScore strict =
      ScoreCulling(edges, CullInconsistentEdges(scene.input, edges, CullingOptions()).edge_kept,
                   scene.is_dynamic);
  EXPECT_LT(literal.culled_boundary, literal.boundary);
  EXPECT_EQ(strict.culled_boundary, strict.boundary);
}

TEST(CullInconsistentEdges, StepMoveWithManyFrames) {
  PointSceneOptions o;
  o.frames = 8;
  o.jump = true;
  const Scores s = RunCulling(o, "jump 8f");
  EXPECT_GE(s.least_squares.Recall(), 0.95);
  EXPECT_GE(s.direct.Recall(), 0.95);
}

}  // namespace
}  // namespace dslam

namespace dslam {
namespace {

// A 3 m static edge measured (noise-free, 5 mm sigma) in two frames whose pose estimates differ
// from the truth by a 1 deg rotation of the second frame: l x dtheta = 5.2 cm, chi-square about
// 27 against 11.3 (3 dof, 99%) from the point noise alone. With a 1 deg rotation sigma declared
// the edge is consistent.
TEST(DirectEdgeTest, RotationCovarianceAbsorbsPoseErrorOfLongEdges) {
  CorrelationInput input;
  input.points_world = {Eigen::Vector3d(-1.5, 0.0, 4.0), Eigen::Vector3d(1.5, 0.0, 4.0)};
  const Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d estimate = Eigen::Isometry3d::Identity();
  const double error_rad = 1.0 * M_PI / 180.0;
  estimate.linear() = Eigen::AngleAxisd(error_rad, Eigen::Vector3d::UnitY()).matrix();
  input.T_camera_world = {truth, estimate};
  for (int frame = 0; frame < 2; ++frame) {
    for (int point = 0; point < 2; ++point) {
      PointObservation obs;
      obs.point = point;
      obs.frame = frame;
      obs.y_camera = input.points_world[point];  // the camera did not move; frame 1's R is off
      obs.covariance = 0.005 * 0.005 * Eigen::Matrix3d::Identity();
      input.observations.push_back(obs);
    }
  }
  const std::vector<GraphEdge> edges = {{0, 1}};
  EXPECT_FALSE(DirectEdgeTest(input, edges, 0.99).edge_kept[0]);
  const double sigma = 1.0 * M_PI / 180.0;
  input.rotation_covariance.assign(2, sigma * sigma * Eigen::Matrix3d::Identity());
  EXPECT_TRUE(DirectEdgeTest(input, edges, 0.99).edge_kept[0]);
}

}  // namespace
}  // namespace dslam
