// The distorted scenario (static_room_distorted): its frames show the scene where OpenCV's
// projection with the sensor's distortion puts it (cv::projectPoints, independent of the
// renderer's cv::undistortPoints maps and of PinholeCamera::Distort), and camera.yaml carries the
// coefficients.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "dslam/io/dataset_io.h"
#include "dslam/synth/sequence.h"
#include "dslam/synth/writer.h"

namespace dslam {
namespace synth {
namespace {

double Median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// Mean absolute difference over the channels of `image` at (u, v) (bilinear) and `colour`.
double ColourDifference(const cv::Mat& image, double u, double v, const cv::Vec3b& colour) {
  cv::Mat patch;
  cv::getRectSubPix(image, cv::Size(1, 1), cv::Point2f(u, v), patch, CV_32F);
  const cv::Vec3f sampled = patch.at<cv::Vec3f>(0, 0);
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) sum += std::abs(sampled[c] - colour[c]);
  return sum / 3.0;
}

TEST(Distortion, FramesShowTheSceneWhereOpenCvProjectsIt) {
  const SyntheticSequence distorted(MakeScenario("static_room_distorted", 1));
  Scenario without = distorted.scenario();
  without.sensor.distortion = Distortion();
  const SyntheticSequence ideal(without);
  const SyntheticFrame a = ideal.RenderFrame(5);
  const SyntheticFrame b = distorted.RenderFrame(5);
  const PinholeCamera& cam = *distorted.camera();
  const Distortion& d = cam.distortion();
  ASSERT_FALSE(d.IsZero());
  std::vector<cv::Point3d> points;
  std::vector<cv::Vec3b> colours;
  std::vector<cv::Point2d> ideal_pixels;
  for (int v = 8; v < cam.height() - 8; v += 7) {
    for (int u = 8; u < cam.width() - 8; u += 7) {
      const double z = a.depth_true_m.at<float>(v, u);
      if (!(z > 0.0)) continue;
      points.emplace_back(z * (u - cam.cx()) / cam.fx(), z * (v - cam.cy()) / cam.fy(), z);
      colours.push_back(a.colour_clean.at<cv::Vec3b>(v, u));
      ideal_pixels.emplace_back(u, v);
    }
  }
  const cv::Matx33d K(cam.fx(), 0, cam.cx(), 0, cam.fy(), cam.cy(), 0, 0, 1);
  std::vector<cv::Point2d> projected;
  cv::projectPoints(points, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K,
                    std::vector<double>{d.k1, d.k2, d.p1, d.p2, d.k3}, projected);
  std::vector<double> where_projected, where_undistorted, depth_error;
  double largest_shift_px = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    const cv::Point2d& p = projected[i];
    if (!(p.x >= 1 && p.y >= 1 && p.x < cam.width() - 2 && p.y < cam.height() - 2)) continue;
    const double shift_px = std::hypot(p.x - ideal_pixels[i].x, p.y - ideal_pixels[i].y);
    largest_shift_px = std::max(largest_shift_px, shift_px);
    where_projected.push_back(ColourDifference(b.colour_clean, p.x, p.y, colours[i]));
    if (shift_px > 3.0) {  // where a missing or wrong distortion would show
      where_undistorted.push_back(
          ColourDifference(b.colour_clean, ideal_pixels[i].x, ideal_pixels[i].y, colours[i]));
    }
    const double z = b.depth_true_m.at<float>(static_cast<int>(std::lround(p.y)),
                                              static_cast<int>(std::lround(p.x)));
    depth_error.push_back(std::abs(z - points[i].z) / points[i].z);
  }
  std::printf(
      "%zu points, largest shift %.1f px; colour difference median %.2f where projected, "
      "%.2f without distortion where it moves the point over 3 px (%zu); depth error median %.4f\n",
      where_projected.size(), largest_shift_px, Median(where_projected), Median(where_undistorted),
      where_undistorted.size(), Median(depth_error));
  ASSERT_GT(where_projected.size(), 4000u);
  EXPECT_GT(largest_shift_px, 10.0);        // the lens moves the border by this much
  EXPECT_LT(Median(where_projected), 0.5);  // measured 0.22 grey levels
  ASSERT_GT(where_undistorted.size(), 1000u);
  // Measured 4.00: the textures' patches are flat, so most points keep their colour anyway.
  EXPECT_GT(Median(where_undistorted), 5.0 * Median(where_projected));
  EXPECT_LT(Median(depth_error), 0.002);
}

TEST(Distortion, CameraYamlCarriesTheCoefficients) {
  const Scenario scenario = MakeScenario("static_room_distorted", 1);
  const std::string path =
      (std::filesystem::path(testing::TempDir()) / "distorted_camera.yaml").string();
  WriteCameraYaml(path, scenario.sensor);
  const Distortion read = LoadCameraYaml(path).camera->distortion();
  const Distortion& written = scenario.sensor.distortion;
  EXPECT_EQ(read.k1, written.k1);
  EXPECT_EQ(read.k2, written.k2);
  EXPECT_EQ(read.p1, written.p1);
  EXPECT_EQ(read.p2, written.p2);
  EXPECT_EQ(read.k3, written.k3);
}

}  // namespace
}  // namespace synth
}  // namespace dslam
