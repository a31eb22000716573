// The correction helpers against a known rigid correction: points, covariances and frame poses
// attached to a keyframe move exactly as the keyframe does.
#include "dslam/loop_closing/pose_correction.h"

#include <stdexcept>

#include <gtest/gtest.h>

#include "loop_closing/ring_graph.h"

namespace dslam {
namespace {

// A keyframe pose and its corrected pose: T_world_keyframe_corrected = C T_world_keyframe with
// a known correction C (rotation about a tilted axis and a translation).
struct KnownCorrection {
  Eigen::Isometry3d C = test::Motion({0.2, -0.1, 0.4}, {0.5, -0.3, 0.2});
  Eigen::Isometry3d T_world_keyframe = test::Motion({-0.3, 0.6, 0.1}, {2.0, 1.0, -0.5});
  Eigen::Isometry3d T_world_keyframe_corrected = C * T_world_keyframe;
};

TEST(PoseCorrection, KeyFrameCorrectionIsTheRigidCorrection) {
  const KnownCorrection k;
  EXPECT_TRUE(
      KeyFrameCorrection(k.T_world_keyframe, k.T_world_keyframe_corrected).isApprox(k.C, 1e-12));
}

TEST(PoseCorrection, PointMovesWithItsKeyFrame) {
  const KnownCorrection k;
  const Eigen::Vector3d p_keyframe(0.3, -0.2, 2.5);  // in the keyframe's optical frame
  const Eigen::Vector3d p_world = k.T_world_keyframe * p_keyframe;
  const Eigen::Vector3d p_corrected =
      CorrectPoint(p_world, k.T_world_keyframe, k.T_world_keyframe_corrected);
  EXPECT_TRUE(p_corrected.isApprox(k.C * p_world, 1e-12));
  EXPECT_TRUE(p_corrected.isApprox(k.T_world_keyframe_corrected * p_keyframe, 1e-12));
}

TEST(PoseCorrection, CovarianceRotatesWithTheCorrection) {
  const KnownCorrection k;
  // Elongated along the keyframe's optical axis, in the keyframe's frame.
  const Eigen::Matrix3d cov_keyframe = Eigen::Vector3d(1e-4, 1e-4, 1e-2).asDiagonal();
  const Eigen::Matrix3d R_world_keyframe = k.T_world_keyframe.rotation();
  const Eigen::Matrix3d cov_world = R_world_keyframe * cov_keyframe * R_world_keyframe.transpose();
  const Eigen::Matrix3d R_corrected = k.T_world_keyframe_corrected.rotation();
  const Eigen::Matrix3d expected = R_corrected * cov_keyframe * R_corrected.transpose();
  EXPECT_TRUE(CorrectPointCovariance(cov_world, k.T_world_keyframe, k.T_world_keyframe_corrected)
                  .isApprox(expected, 1e-12));
}

TEST(PoseCorrection, FramePoseKeepsItsPoseRelativeToTheKeyFrame) {
  const KnownCorrection k;
  const Eigen::Isometry3d T_keyframe_camera = test::Motion({0.01, 0.02, -0.03}, {0.05, 0, 0.1});
  const Eigen::Isometry3d T_world_camera = k.T_world_keyframe * T_keyframe_camera;
  const Eigen::Isometry3d corrected =
      CorrectPose(T_world_camera, k.T_world_keyframe, k.T_world_keyframe_corrected);
  EXPECT_TRUE(corrected.isApprox(k.T_world_keyframe_corrected * T_keyframe_camera, 1e-12));
  EXPECT_TRUE(
      (k.T_world_keyframe_corrected.inverse() * corrected).isApprox(T_keyframe_camera, 1e-12));
}

TEST(PoseCorrection, FramePoseThroughTheGraphsReferenceKeyFrame) {
  const KnownCorrection k;
  PoseGraph graph;
  graph.nodes[7] = {k.T_world_keyframe, false};
  PoseGraphResult result;
  result.T_world_camera[7] = k.T_world_keyframe_corrected;
  const Eigen::Isometry3d T_world_camera =
      k.T_world_keyframe * test::Motion({0, 0.1, 0}, {0, 0, 0.3});
  EXPECT_TRUE(
      CorrectFramePose(T_world_camera, 7, graph, result).isApprox(k.C * T_world_camera, 1e-12));
  EXPECT_THROW(CorrectFramePose(T_world_camera, 8, graph, result), std::invalid_argument);
  graph.nodes[8] = {k.T_world_keyframe, false};  // in the graph, not in the result
  EXPECT_THROW(CorrectFramePose(T_world_camera, 8, graph, result), std::invalid_argument);
}

}  // namespace
}  // namespace dslam
