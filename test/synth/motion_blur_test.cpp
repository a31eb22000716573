// Tests of the motion blur of synthetic colour images (motion_blur.h): the sub-frame rule, the
// image-path measure, exposure 0 = the sharp render, and a blurred fast_rotation frame.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "dslam/synth/motion_blur.h"
#include "dslam/synth/render.h"
#include "dslam/synth/sequence.h"

namespace dslam {
namespace synth {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

/// Mean Sobel gradient magnitude [grey levels / px] of the grey image of a CV_8UC3 image.
double MeanGradient(const cv::Mat& bgr) {
  cv::Mat grey, gx, gy, magnitude;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::Sobel(grey, gx, CV_32F, 1, 0);
  cv::Sobel(grey, gy, CV_32F, 0, 1);
  cv::magnitude(gx, gy, magnitude);
  return cv::mean(magnitude)[0];
}

double MeanGrey(const cv::Mat& bgr) {
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  return cv::mean(grey)[0];
}

/// Largest image distance [px] a pixel (every `stride`-th, depth from `depth_m` at `T_ref`) moves
/// between the camera poses `a` and `b`; brute force, independent of MaxImagePathPx.
double MaxDisplacementPx(const PinholeCamera& cam, const cv::Mat& depth_m,
                         const Eigen::Isometry3d& T_ref, const Eigen::Isometry3d& a,
                         const Eigen::Isometry3d& b, int stride) {
  double longest = 0.0;
  for (int v = 0; v < cam.height(); v += stride) {
    for (int u = 0; u < cam.width(); u += stride) {
      const Eigen::Vector3d p_world =
          T_ref * cam.BackProject(Eigen::Vector2d(u, v), depth_m.at<float>(v, u));
      const Eigen::Vector2d uv_a = cam.Project(a.inverse() * p_world);
      longest = std::max(longest, (cam.Project(b.inverse() * p_world) - uv_a).norm());
    }
  }
  return longest;
}

TEST(SynthMotionBlur, SubframeCountRule) {
  ExposureParams e;  // max_step_px 1.5, max_subframes 15
  EXPECT_EQ(SubframeCount(0.0, e), 1);
  EXPECT_EQ(SubframeCount(1.5, e), 1);
  EXPECT_EQ(SubframeCount(1.51, e), 3);  // 2 needed, rounded up to odd
  EXPECT_EQ(SubframeCount(4.5, e), 3);
  EXPECT_EQ(SubframeCount(4.6, e), 5);
  EXPECT_EQ(SubframeCount(9.0, e), 7);  // 6 needed
  EXPECT_EQ(SubframeCount(22.5, e), 15);
  EXPECT_EQ(SubframeCount(100.0, e), 15);  // cap
  e.max_subframes = 14;
  EXPECT_EQ(SubframeCount(100.0, e), 13);  // cap rounded down to odd
  const std::vector<double> offsets = SubframeOffsets(0.015, 5);
  const std::vector<double> expected = {-0.006, -0.003, 0.0, 0.003, 0.006};
  ASSERT_EQ(offsets.size(), expected.size());
  for (size_t k = 0; k < offsets.size(); ++k) EXPECT_NEAR(offsets[k], expected[k], 1e-15);
  EXPECT_EQ(offsets[2], 0.0);  // exactly: the middle sub-frame is the sharp render
  EXPECT_EQ(SubframeOffsets(0.015, 1), std::vector<double>{0.0});
}

TEST(SynthMotionBlur, MeanColourRoundsHalfUp) {
  const cv::Mat a(2, 2, CV_8UC3, cv::Scalar(10, 0, 255)), b(2, 2, CV_8UC3, cv::Scalar(11, 1, 255));
  const cv::Mat mean = MeanColour({a, b});
  EXPECT_EQ(mean.at<cv::Vec3b>(1, 1), cv::Vec3b(11, 1, 255));  // 10.5 -> 11, 0.5 -> 1
}

TEST(SynthMotionBlur, ImagePathOfRollAndTranslation) {
  const PinholeCamera cam(640, 480, 525.0, 525.0, 319.5, 239.5);
  const cv::Mat depth(480, 640, CV_32FC1, cv::Scalar(2.0f));
  const double roll = 2.0 * kDegToRad;
  std::vector<Eigen::Isometry3d> path;
  for (int k = 0; k <= 4; ++k) {
    path.emplace_back(Eigen::AngleAxisd(roll * (k / 4.0 - 0.5), Eigen::Vector3d::UnitZ()));
  }
  // Roll about the optical axis: the corners (radius 399.3 px) move along 4 chords of an arc.
  const double radius = std::hypot(319.5, 239.5);
  const double chords = 4.0 * 2.0 * radius * std::sin(roll / 8.0);
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  EXPECT_NEAR(MaxImagePathPx(cam, depth, I, path, 8), chords, 1e-9);
  // Translation of 1 cm along x: f * 0.01 / 2 px for a wall at 2 m, nothing at infinity.
  Eigen::Isometry3d shifted = I;
  shifted.translation().x() = 0.01;
  EXPECT_NEAR(MaxImagePathPx(cam, depth, I, {I, shifted}, 8), 2.625, 1e-9);
  const cv::Mat nothing(480, 640, CV_32FC1, cv::Scalar(0.0f));
  EXPECT_NEAR(MaxImagePathPx(cam, nothing, I, {I, shifted}, 8), 0.0, 1e-12);
}

TEST(SynthMotionBlur, ZeroExposureGivesTheSharpRender) {
  Scenario scenario = MakeScenario("fast_rotation", 1);
  scenario.camera.exposure.exposure_s = 0.0;
  const SyntheticSequence sequence(scenario);
  const SyntheticFrame f = sequence.RenderFrame(3);
  const RenderedImages sharp =
      RenderScene(sequence.GeometryAt(3), *sequence.camera(), sequence.PoseOf(3));
  EXPECT_EQ(cv::norm(f.colour_clean, sharp.colour, cv::NORM_INF), 0.0);
  EXPECT_EQ(f.colour_subframes, 1);
  EXPECT_EQ(f.blur_path_px, 0.0);
}

TEST(SynthMotionBlur, SlowCameraNeedsOneSubframe) {
  // walking_static's camera jitters by mm: with a 15 ms exposure the path stays below 1.5 px and
  // the frame equals the sharp one byte for byte.
  Scenario blurred = MakeScenario("walking_static", 1);
  blurred.camera.exposure.exposure_s = 0.015;
  const SyntheticFrame f = SyntheticSequence(blurred).RenderFrame(20);
  const SyntheticFrame g = SyntheticSequence(MakeScenario("walking_static", 1)).RenderFrame(20);
  EXPECT_GT(f.blur_path_px, 0.0);
  EXPECT_LT(f.blur_path_px, 1.5);
  EXPECT_EQ(f.colour_subframes, 1);
  EXPECT_EQ(cv::norm(f.frame.colour, g.frame.colour, cv::NORM_INF), 0.0);
}

TEST(SynthMotionBlur, FastRotationFrameIsBlurredByTheRule) {
  const Scenario scenario = MakeScenario("fast_rotation", 1);
  Scenario sharp_scenario = scenario;
  sharp_scenario.camera.exposure.exposure_s = 0.0;
  const SyntheticSequence sequence(scenario);
  const int index = 1;  // t = 0 has the largest rates of all axes; frame 1 is 33 ms later
  const SyntheticFrame f = sequence.RenderFrame(index);
  const SyntheticFrame sharp = SyntheticSequence(sharp_scenario).RenderFrame(index);
  const double g_blur = MeanGradient(f.colour_clean), g_sharp = MeanGradient(sharp.colour_clean);
  const double mean_blur = MeanGrey(f.colour_clean), mean_sharp = MeanGrey(sharp.colour_clean);
  std::printf(
      "frame %d: path %.2f px, %d sub-frames; mean gradient %.2f (sharp %.2f); mean grey "
      "%.2f (sharp %.2f)\n",
      index, f.blur_path_px, f.colour_subframes, g_blur, g_sharp, mean_blur, mean_sharp);
  EXPECT_GE(f.colour_subframes, 9);
  EXPECT_LT(g_blur, 0.8 * g_sharp);
  EXPECT_NEAR(mean_blur, mean_sharp, 1.0);
  // Depth, mask and pose are those of the exposure's middle: the sharp frame's.
  EXPECT_EQ(cv::norm(f.depth_true_m, sharp.depth_true_m, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(f.depth_units, sharp.depth_units, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(f.mask, sharp.mask, cv::NORM_INF), 0.0);
  EXPECT_TRUE(f.T_world_camera.isApprox(sharp.T_world_camera, 0.0));
  // The documented rule, checked brute force: the path of every 2nd pixel over 16 segments, and
  // the image motion between consecutive sub-frames of every 4th pixel.
  const double t = index / scenario.fps;
  const ExposureParams& e = scenario.camera.exposure;
  const double fine_path =
      MaxImagePathPx(*sequence.camera(), f.depth_true_m, f.T_world_camera,
                     ExposurePath(scenario.camera, t, scenario.seed, e.exposure_s, 16), 2);
  EXPECT_NEAR(f.blur_path_px, fine_path, 0.01 * fine_path);
  EXPECT_EQ(f.colour_subframes, SubframeCount(f.blur_path_px, e));
  const std::vector<double> offsets = SubframeOffsets(e.exposure_s, f.colour_subframes);
  for (size_t k = 1; k < offsets.size(); ++k) {
    const double step =
        MaxDisplacementPx(*sequence.camera(), f.depth_true_m, f.T_world_camera,
                          CameraPoseAt(scenario.camera, t + offsets[k - 1], scenario.seed),
                          CameraPoseAt(scenario.camera, t + offsets[k], scenario.seed), 4);
    EXPECT_LE(step, e.max_step_px) << "between sub-frames " << k - 1 << " and " << k;
  }
  // A pure function of (scenario, seed, index).
  EXPECT_EQ(cv::norm(sequence.RenderFrame(index).colour_clean, f.colour_clean, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace synth
}  // namespace dslam
