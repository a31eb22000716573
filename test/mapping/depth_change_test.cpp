// Depth-change seeds (depth_change.h) on rendered depth images: a flat wall 3 m in front of the
// camera, and a box 1 m in front of it that appears, seen from cameras shifted sideways, with
// depth noise of the configured model drawn from a seeded RNG.
#include "dslam/mapping/depth_change.h"

#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "dslam/core/depth_uncertainty.h"
#include "dslam/mapping/dynamic_mask.h"

namespace dslam {
namespace {

constexpr int kWidth = 640, kHeight = 480;
constexpr double kWallZ = 3.0, kBoxZ = 2.0;

/// An axis-aligned box face in the world (x, y ranges [m]) at depth kBoxZ.
struct Box {
  double x0, x1, y0, y1;
};

/// The depth model of the camera Render() simulates: independent Gaussian noise of
/// 0.0014 d^2 + 0.001 m per pixel (a precise camera; the default models a real one, looser).
DepthNoiseConfig Noise() {
  DepthNoiseConfig noise;
  noise.sigma_d_quadratic = 1.4e-3;
  noise.sigma_d_constant_m = 1.0e-3;
  return noise;
}

/// The depth image of a camera at (tx, 0, 0) looking along world z (identity rotation): the wall
/// at z = kWallZ, the boxes in front of it; Gaussian noise of sigma_d(z) when `rng` is given.
RgbdFrame Render(double tx, const std::vector<Box>& boxes, std::mt19937* rng) {
  RgbdFrame frame;
  frame.camera = std::make_shared<PinholeCamera>(kWidth, kHeight, 525, 525, 319.5, 239.5);
  frame.depth_m = cv::Mat(kHeight, kWidth, CV_32FC1);
  frame.colour = cv::Mat(kHeight, kWidth, CV_8UC3, cv::Scalar(200, 200, 200));
  const DepthNoiseConfig noise = Noise();
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (int v = 0; v < kHeight; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      const double x = (u - 319.5) / 525.0 * kBoxZ + tx, y = (v - 239.5) / 525.0 * kBoxZ;
      double z = kWallZ;
      for (const Box& b : boxes) {
        if (x >= b.x0 && x <= b.x1 && y >= b.y0 && y <= b.y1) z = kBoxZ;
      }
      if (rng != nullptr) z += DepthSigma(z, noise) * gauss(*rng);
      frame.depth_m.at<float>(v, u) = static_cast<float>(z);
    }
  }
  return frame;
}

Eigen::Isometry3d CameraAt(double tx) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = tx;
  return T;
}

DynamicMaskConfig SeedConfig() { return DynamicMaskConfig(); }

/// Share of the cells whose centre pixel sees the box at camera x `tx` that are labelled, and
/// the number of labelled cells that see the wall.
void Coverage(const DynamicMask& mask, const RgbdFrame& frame, double* box_share, int* on_wall) {
  int box = 0, hit = 0;
  *on_wall = 0;
  for (int r = 0; r < mask.labels.rows; ++r) {
    for (int c = 0; c < mask.labels.cols; ++c) {
      const int u = c * mask.decimation + mask.decimation / 2;
      const int v = r * mask.decimation + mask.decimation / 2;
      const bool on_box = frame.depth_m.at<float>(v, u) < 0.5 * (kWallZ + kBoxZ);
      const bool labelled = mask.labels.at<uint16_t>(r, c) != 0;
      box += on_box;
      hit += on_box && labelled;
      *on_wall += !on_box && labelled;
    }
  }
  *box_share = box > 0 ? static_cast<double>(hit) / box : 0.0;
}

TEST(DepthReference, KeepsOneFramePerIntervalAndTheNewest) {
  DynamicMaskConfig config = SeedConfig();
  config.depth_change_interval_s = 0.2;
  config.depth_change_references = 2;
  DepthReference reference(config, Noise());
  const RgbdFrame wall = Render(0.0, {}, nullptr);
  for (int i = 0; i < 30; ++i) reference.Add(wall, CameraAt(0.0), i / 30.0);
  EXPECT_EQ(reference.size(), 2);
  reference.Add(wall, CameraAt(0.0), 0.0);  // back in time: starts again
  EXPECT_EQ(reference.size(), 1);
}

TEST(DepthReference, ChangedOnlyInFrontOfWhatWasSeen) {
  DepthReference reference(SeedConfig(), Noise());
  reference.Add(Render(0.0, {}, nullptr), CameraAt(0.0), 0.0);
  EXPECT_TRUE(reference.Changed(Eigen::Vector3d(0.1, 0.0, kBoxZ), kBoxZ));
  EXPECT_FALSE(reference.Changed(Eigen::Vector3d(0.1, 0.0, kWallZ), kWallZ));
  // Within the margin (0.1 m + 3 sigma at 2.9 m, about 0.16 m): not a change.
  EXPECT_FALSE(reference.Changed(Eigen::Vector3d(0.1, 0.0, kWallZ - 0.1), kWallZ - 0.1));
  // Behind the wall (occluded then): not a change.
  EXPECT_FALSE(reference.Changed(Eigen::Vector3d(0.1, 0.0, kWallZ + 1.0), kWallZ + 1.0));
}

TEST(DepthReference, FrameTestAgreesWithTheWorldFrameTest) {
  // References of the wall and of a box before it, seen from x = 0 and 0.2 m; the test of a frame
  // at x = 0.5 m on its points (optical frame) answers as Changed() on them in the world frame.
  DepthReference reference(SeedConfig(), Noise());
  reference.Add(Render(0.0, {}, nullptr), CameraAt(0.0), 0.0);
  reference.Add(Render(0.2, {{0.3, 0.8, -0.4, 0.4}}, nullptr), CameraAt(0.2), 0.2);
  const Eigen::Isometry3d T_world_camera = CameraAt(0.5);
  const DepthReference::FrameTest test = reference.ForFrame(T_world_camera);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> lateral(-1.0, 1.0), depth(0.5, 4.0);
  std::vector<Eigen::Vector3d> points_camera;
  for (int i = 0; i < 2000; ++i) points_camera.emplace_back(lateral(rng), lateral(rng), depth(rng));
  const std::vector<uint8_t> answers = test.ChangedAll(points_camera);
  ASSERT_EQ(answers.size(), points_camera.size());
  int changed = 0, unchanged = 0;
  for (size_t i = 0; i < points_camera.size(); ++i) {
    const Eigen::Vector3d& p = points_camera[i];
    const bool expected = reference.Changed(T_world_camera * p, p.z());
    EXPECT_EQ(answers[i] != 0, expected) << p.transpose();
    (expected ? changed : unchanged) += 1;
  }
  EXPECT_GT(changed, 200);  // both answers occur
  EXPECT_GT(unchanged, 200);
}

TEST(DepthChangeSeeds, BoxAppearingInFrontOfTheWallIsMasked) {
  std::mt19937 rng(7);
  DepthReference reference(SeedConfig(), Noise());
  reference.Add(Render(0.0, {}, &rng), CameraAt(0.0), 0.0);
  const Box box{-0.2, 0.3, -0.5, 0.4};
  const RgbdFrame frame = Render(0.1, {box}, &rng);
  // Two candidate points on the box, one verified static point on the wall; no unmarked point.
  std::vector<ObservedPoint> points(3);
  points[0].id = 1, points[0].uv_raw = Eigen::Vector2d(300, 240), points[0].is_candidate = true;
  points[1].id = 2, points[1].uv_raw = Eigen::Vector2d(330, 200), points[1].is_candidate = true;
  points[2].id = 3, points[2].uv_raw = Eigen::Vector2d(50, 50);
  const DynamicMask without =
      ComputeDynamicMask(frame, CameraAt(0.1), points, SeedConfig(), {}, 0.0, 0, nullptr);
  EXPECT_TRUE(without.regions.empty());
  const DynamicMask mask =
      ComputeDynamicMask(frame, CameraAt(0.1), points, SeedConfig(), {}, 0.0, 0, &reference);
  ASSERT_EQ(mask.regions.size(), 1u);
  double box_share = 0.0;
  int on_wall = 0;
  Coverage(mask, frame, &box_share, &on_wall);
  EXPECT_GT(box_share, 0.95);
  EXPECT_EQ(on_wall, 0);
  EXPECT_EQ(mask.regions[0].points, (std::vector<PointId>{1, 2}));
  EXPECT_NEAR(mask.regions[0].centroid_world.x(), 0.05, 0.02);
  EXPECT_NEAR(mask.regions[0].centroid_world.z(), kBoxZ, 0.02);
}

TEST(DepthChangeSeeds, VerifiedStaticCellsAreNeverEntered) {
  DepthReference reference(SeedConfig(), Noise());
  reference.Add(Render(0.0, {}, nullptr), CameraAt(0.0), 0.0);
  const RgbdFrame frame = Render(0.0, {{-0.2, 0.3, -0.5, 0.4}}, nullptr);
  std::vector<ObservedPoint> points(1);
  points[0].uv_raw = Eigen::Vector2d(330, 250);  // verified static, on the box
  const DynamicMask mask =
      ComputeDynamicMask(frame, CameraAt(0.0), points, SeedConfig(), {}, 0.0, 0, &reference);
  ASSERT_EQ(mask.regions.size(), 1u);
  EXPECT_EQ(mask.LabelAt(330, 250), 0);
  EXPECT_NE(mask.LabelAt(310, 230), 0);
}

TEST(DepthChangeSeeds, StaticWallAndBoxSeenFromMovingCameraGiveNoSeeds) {
  std::mt19937 rng(11);
  const Box box{-0.2, 0.3, -0.5, 0.4};  // in both frames: static
  DepthReference reference(SeedConfig(), Noise());
  for (int i = 0; i < 3; ++i) {
    reference.Add(Render(0.05 * i, {box}, &rng), CameraAt(0.05 * i), 0.25 * i);
  }
  ASSERT_EQ(reference.size(), 3);
  for (int i = 3; i < 6; ++i) {
    const RgbdFrame frame = Render(0.05 * i, {box}, &rng);
    const DynamicMask mask =
        ComputeDynamicMask(frame, CameraAt(0.05 * i), {}, SeedConfig(), {}, 0.0, 0, &reference);
    EXPECT_TRUE(mask.regions.empty()) << "frame " << i;
    EXPECT_EQ(mask.MaskedShare(), 0.0) << "frame " << i;
  }
  // The wall alone with noise, seen from where the references were.
  const RgbdFrame wall = Render(0.0, {}, &rng);
  DepthReference wall_reference(SeedConfig(), Noise());
  wall_reference.Add(Render(0.0, {}, &rng), CameraAt(0.0), 0.0);
  EXPECT_EQ(ComputeDynamicMask(wall, CameraAt(0.0), {}, SeedConfig(), {}, 0.0, 0, &wall_reference)
                .MaskedShare(),
            0.0);
}

TEST(DepthChangeSeeds, SmallGroupsAreLeftOut) {
  DynamicMaskConfig config = SeedConfig();
  DepthReference reference(config, Noise());
  reference.Add(Render(0.0, {}, nullptr), CameraAt(0.0), 0.0);
  // 0.08 m x 0.08 m at 2 m: 21 x 21 px, 5 x 5 cells of which 3 x 3 tested (stride 2): 36 cells
  // < depth_change_min_cells (40).
  const RgbdFrame frame = Render(0.0, {{0.0, 0.08, 0.0, 0.08}}, nullptr);
  EXPECT_TRUE(
      ComputeDynamicMask(frame, CameraAt(0.0), {}, config, {}, 0.0, 0, &reference).regions.empty());
  config.depth_change_min_cells = 16;
  EXPECT_EQ(
      ComputeDynamicMask(frame, CameraAt(0.0), {}, config, {}, 0.0, 0, &reference).regions.size(),
      1u);
}

}  // namespace
}  // namespace dslam
