// Tests of the synthetic renderer's geometry, actors and masks.
#include <gtest/gtest.h>

#include <cmath>

#include "dslam/synth/actors.h"
#include "dslam/synth/render.h"
#include "dslam/synth/sequence.h"

namespace dslam {
namespace synth {
namespace {

TEST(SynthGeometry, BoxHitFromOutsideAndInside) {
  Box box;
  box.T_world_box = Eigen::Translation3d(0.0, 0.0, 5.0);
  box.half_extent = Eigen::Vector3d(1.0, 1.0, 1.0);
  const Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  BoxInCamera prepared = PrepareBox(box, T_world_camera);
  int face = -1;
  EXPECT_NEAR(IntersectBox(box, prepared, Eigen::Vector3d(0.1, 0.0, 1.0), 1e-3, &face), 4.0, 1e-12);
  EXPECT_EQ(face, 4);  // z- face
  EXPECT_LT(IntersectBox(box, prepared, Eigen::Vector3d(0.5, 0.0, 1.0), 1e-3, &face), 0.0);
  box.inward = true;
  box.T_world_box = Eigen::Isometry3d::Identity();
  box.half_extent = Eigen::Vector3d(2.0, 2.0, 3.0);
  prepared = PrepareBox(box, T_world_camera);
  EXPECT_NEAR(IntersectBox(box, prepared, Eigen::Vector3d(0.0, 0.0, 1.0), 1e-3, &face), 3.0, 1e-12);
  EXPECT_EQ(face, 5);
  EXPECT_NEAR(IntersectBox(box, prepared, Eigen::Vector3d(1.0, 0.0, 1.0), 1e-3, &face), 2.0, 1e-12);
  EXPECT_EQ(face, 1);
}

TEST(SynthGeometry, TriangleHit) {
  Eigen::Vector2d bary;
  const Eigen::Vector3d a(-1, -1, 2), b(1, -1, 2), c(-1, 1, 2);
  EXPECT_NEAR(IntersectTriangle(a, b, c, Eigen::Vector3d(-0.1, -0.1, 1.0), 1e-3, &bary), 2.0,
              1e-12);
  EXPECT_NEAR(bary.x(), 0.4, 1e-12);
  EXPECT_NEAR(bary.y(), 0.4, 1e-12);
  EXPECT_LT(IntersectTriangle(a, b, c, Eigen::Vector3d(0.3, 0.3, 1.0), 1e-3, &bary), 0.0);
}

TEST(SynthActors, WalkerSpeedGaitAndPause) {
  WalkerParams w;
  w.path_m = {{0.0, 0.0}, {4.0, 0.0}};
  w.dwell_s = {0.0, 1.0};
  const WalkerState s0 = WalkerStateAt(w, 0.0), s1 = WalkerStateAt(w, 1.5);
  EXPECT_NEAR((s1.position_m - s0.position_m).norm(), 1.5, 1e-9);  // 1 m/s
  EXPECT_NEAR(s1.gait_phase_rad - s0.gait_phase_rad, 2.0 * M_PI * 1.5 / w.stride_m, 1e-9);
  const WalkerState paused = WalkerStateAt(w, 4.5);  // arrived at 4 s, pausing 1 s
  EXPECT_NEAR(paused.position_m.x(), 4.0, 1e-9);
  EXPECT_NEAR(paused.idle_time_s, 0.5, 1e-9);
  // Limbs swing: the boxes of the walker differ between two instants a quarter stride apart.
  SceneGeometry a, b;
  AppendWalker(w, 0.0, 1, &a);
  AppendWalker(w, 0.35, 1, &b);
  ASSERT_EQ(a.boxes.size(), 10u);
  const Eigen::Matrix3d thigh_a = a.boxes[4].T_world_box.linear();
  const Eigen::Matrix3d thigh_b = b.boxes[4].T_world_box.linear();
  EXPECT_GT((thigh_a - thigh_b).norm(), 0.3);
}

TEST(SynthActors, SlowBoxMovesThreeMillimetresPerFrame) {
  const Scenario s = MakeScenario("slow_box", 1);
  SceneGeometry a, b;
  AppendMovingBox(s.boxes[0], 1.0, 1, &a);
  AppendMovingBox(s.boxes[0], 1.0 + 1.0 / 30.0, 1, &b);
  const double step =
      (a.boxes[0].T_world_box.translation() - b.boxes[0].T_world_box.translation()).norm();
  EXPECT_NEAR(step, 0.003, 1e-9);
}

TEST(SynthActors, SheetDeformsWithFixedTopEdge) {
  SheetParams sheet;
  EXPECT_DOUBLE_EQ(SheetDisplacement(sheet, 0.4, 0.0, 1.3), 0.0);
  EXPECT_GT(
      std::abs(SheetDisplacement(sheet, 0.4, 1.6, 0.0) - SheetDisplacement(sheet, 0.4, 1.6, 0.4)),
      0.02);
  SceneGeometry scene;
  AppendSheet(sheet, 0.0, 3, &scene);
  EXPECT_EQ(scene.triangles.size(), static_cast<size_t>(2 * sheet.columns * sheet.rows));
}

/// Every 9th pixel: the culled, parallel renderer agrees with a brute-force ray cast, so the mask
/// holds exactly the ids of the objects the pixel rays hit first.
void ExpectRenderMatchesBruteForce(const std::string& name, int index) {
  const SyntheticSequence sequence(MakeScenario(name, 2));
  const SceneGeometry scene = sequence.GeometryAt(index);
  const Eigen::Isometry3d T_world_camera = sequence.PoseOf(index);
  const RenderedImages images = RenderScene(scene, *sequence.camera(), T_world_camera);
  int moving = 0, checked = 0;
  for (int v = 0; v < images.mask.rows; v += 9) {
    for (int u = 0; u < images.mask.cols; u += 9) {
      const PixelHit hit = CastPixelRay(scene, *sequence.camera(), T_world_camera, u, v);
      ASSERT_TRUE(hit.hit);
      EXPECT_EQ(images.mask.at<uint16_t>(v, u), hit.object_id) << name << " at " << u << "," << v;
      EXPECT_NEAR(images.depth_m.at<float>(v, u), hit.depth_m, 1e-5 * hit.depth_m);
      moving += hit.object_id != 0;
      ++checked;
    }
  }
  EXPECT_GT(moving, checked / 20) << name << ": the moving object should be in view";
}

TEST(SynthRender, MaskAndDepthMatchBruteForceRayCast) {
  ExpectRenderMatchesBruteForce("walking", 45);
  ExpectRenderMatchesBruteForce("nonrigid_sheet", 20);
  ExpectRenderMatchesBruteForce("slow_box", 10);
}

}  // namespace
}  // namespace synth
}  // namespace dslam
