// The structured-light depth model of the synthetic sensor (scenario.h: StructuredLightParams):
// smooth disparity error fields, quantised disparity, an error part fixed to the sensor, edge
// bleeding; with seeded noise whose statistics are known.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "dslam/synth/sequence.h"
#include "dslam/synth/structured_light.h"

namespace dslam {
namespace synth {
namespace {

double Correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double ma = 0, mb = 0;
  for (size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
  ma /= a.size(), mb /= b.size();
  double ab = 0, aa = 0, bb = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    ab += (a[i] - ma) * (b[i] - mb), aa += (a[i] - ma) * (a[i] - ma),
        bb += (b[i] - mb) * (b[i] - mb);
  }
  return ab / std::sqrt(aa * bb);
}

TEST(SmoothField, UnitVarianceOnAverageAndSmooth) {
  const SmoothField field(2048, 2048, 16.0, 7);
  std::vector<double> here, near, far;
  for (int v = 0; v < 2000; v += 7) {
    for (int u = 0; u < 1900; u += 5) {
      here.push_back(field.At(u, v));
      near.push_back(field.At(u + 2, v));
      far.push_back(field.At(u + 96, v));
    }
  }
  double sum = 0, sum_sq = 0;
  for (double x : here) sum += x, sum_sq += x * x;
  const double mean = sum / here.size();
  EXPECT_NEAR(mean, 0.0, 0.05);
  EXPECT_NEAR(sum_sq / here.size() - mean * mean, 1.0, 0.1);
  EXPECT_GT(Correlation(here, near), 0.9);           // 2 px: nearly the same value
  EXPECT_LT(std::abs(Correlation(here, far)), 0.1);  // 6 cells apart: independent
}

/// Disparity errors [px] of `f`'s pixels away from depth edges (no bleeding possible there), with
/// their pixels' indices; and the share of the measured disparities on the quantisation grid.
struct DisparityErrors {
  std::vector<double> error_px;
  std::vector<int> pixel;
  double on_grid_share = 0.0;
};

DisparityErrors ErrorsAwayFromEdges(const SyntheticFrame& f, const SensorParams& s) {
  const double fb = s.fx * s.structured_light.baseline_m,
               step = s.structured_light.disparity_step_px;
  cv::Mat nearest;
  cv::erode(f.depth_true_m, nearest, cv::getStructuringElement(cv::MORPH_RECT, {5, 5}));
  DisparityErrors out;
  int on_grid = 0;
  for (int v = 0; v < f.depth_true_m.rows; ++v) {
    for (int u = 0; u < f.depth_true_m.cols; ++u) {
      const double truth = f.depth_true_m.at<float>(v, u),
                   measured = f.frame.depth_m.at<float>(v, u);
      if (measured <= 0.0 || truth - nearest.at<float>(v, u) > s.edge_jump_m) continue;
      const double disparity = fb / measured;
      on_grid += std::abs(disparity / step - std::round(disparity / step)) < 0.02;
      out.error_px.push_back(disparity - fb / truth);
      out.pixel.push_back(v * f.depth_true_m.cols + u);
    }
  }
  out.on_grid_share = static_cast<double>(on_grid) / out.error_px.size();
  return out;
}

TEST(StructuredLight, DisparityIsQuantisedWithTheConfiguredError) {
  const SyntheticSequence sequence(MakeScenario("static_room_kinect", 2));
  const SensorParams& s = sequence.scenario().sensor;
  const StructuredLightParams& p = s.structured_light;
  ASSERT_TRUE(p.enabled);
  const DisparityErrors e = ErrorsAwayFromEdges(sequence.RenderFrame(10), s);
  ASSERT_GT(e.error_px.size(), 200000u);
  EXPECT_GT(e.on_grid_share, 0.99);  // depth PNG units move a disparity by < 0.01 step
  double sum = 0, sum_sq = 0;
  for (double x : e.error_px) sum += x, sum_sq += x * x;
  const double mean = sum / e.error_px.size();
  const double expected =
      std::sqrt(p.fixed_sigma_px * p.fixed_sigma_px + p.frame_sigma_px * p.frame_sigma_px +
                p.pixel_sigma_px * p.pixel_sigma_px +
                p.disparity_step_px * p.disparity_step_px / 12.0);  // 0.148
  EXPECT_NEAR(std::sqrt(sum_sq / e.error_px.size() - mean * mean), expected, 0.2 * expected);
  EXPECT_LT(std::abs(mean), 0.3 * expected);
}

/// The fixed field: the same pixel's disparity error in two frames correlates by about the fixed
/// field's share of the variance (0.01 / 0.0218 = 0.46); the Gaussian model's errors do not.
TEST(StructuredLight, PartOfTheErrorStaysWithThePixel) {
  const SyntheticSequence sequence(MakeScenario("static_room_kinect", 2));
  const SensorParams& s = sequence.scenario().sensor;
  const DisparityErrors a = ErrorsAwayFromEdges(sequence.RenderFrame(10), s);
  const DisparityErrors b = ErrorsAwayFromEdges(sequence.RenderFrame(40), s);
  std::vector<double> at_a, at_b;
  for (size_t i = 0, j = 0; i < a.pixel.size() && j < b.pixel.size();) {
    if (a.pixel[i] < b.pixel[j]) {
      ++i;
    } else if (b.pixel[j] < a.pixel[i]) {
      ++j;
    } else {
      at_a.push_back(a.error_px[i++]);
      at_b.push_back(b.error_px[j++]);
    }
  }
  ASSERT_GT(at_a.size(), 200000u);
  const double correlation = Correlation(at_a, at_b);
  EXPECT_GT(correlation, 0.25);
  EXPECT_LT(correlation, 0.65);
}

/// Background pixels within bleed_px of a nearer surface read its depth with bleed_probability.
TEST(StructuredLight, TheNearerDepthBleedsOntoTheFartherAtEdges) {
  const SyntheticSequence sequence(MakeScenario("walking_kinect", 1));
  const SensorParams& s = sequence.scenario().sensor;
  const SyntheticFrame f = sequence.RenderFrame(30);
  cv::Mat nearest;
  const int size = 2 * s.structured_light.bleed_px + 1;
  cv::erode(f.depth_true_m, nearest, cv::getStructuringElement(cv::MORPH_RECT, {size, size}));
  int eligible = 0, bled = 0;
  for (int v = 0; v < f.depth_true_m.rows; ++v) {
    for (int u = 0; u < f.depth_true_m.cols; ++u) {
      const double truth = f.depth_true_m.at<float>(v, u),
                   measured = f.frame.depth_m.at<float>(v, u);
      const double near = nearest.at<float>(v, u);
      if (measured <= 0.0 || truth - near <= s.edge_jump_m) continue;
      ++eligible;
      bled += std::abs(measured - near) < std::abs(measured - truth);
    }
  }
  ASSERT_GT(eligible, 500);
  EXPECT_NEAR(static_cast<double>(bled) / eligible, s.structured_light.bleed_probability, 0.08);
}

/// A name with "_kinect" after another scenario's is that scenario with the structured-light
/// depth: the same walkers, camera and frames; an unknown base name is refused.
TEST(StructuredLight, KinectScenariosAreTheirBaseWithStructuredLight) {
  for (const char* base : {"static_room", "walking", "close_person", "fast_rotation"}) {
    const Scenario plain = MakeScenario(base, 3);
    const Scenario kinect = MakeScenario(std::string(base) + "_kinect", 3);
    EXPECT_EQ(kinect.name, std::string(base) + "_kinect");
    EXPECT_FALSE(plain.sensor.structured_light.enabled) << base;
    EXPECT_TRUE(kinect.sensor.structured_light.enabled) << base;
    EXPECT_EQ(kinect.frames, plain.frames) << base;
    EXPECT_EQ(kinect.walkers.size(), plain.walkers.size()) << base;
    EXPECT_EQ(kinect.camera.kind, plain.camera.kind) << base;
  }
  EXPECT_THROW(MakeScenario("no_such_scene_kinect", 1), std::invalid_argument);
}

}  // namespace
}  // namespace synth
}  // namespace dslam
