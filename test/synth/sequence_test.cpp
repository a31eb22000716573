// Tests of synthetic sequences: depth noise model, ground truth vs images, determinism, files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <opencv2/features2d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "dslam/io/dataset_io.h"
#include "dslam/io/trajectory_io.h"
#include "dslam/synth/sequence.h"
#include "dslam/synth/writer.h"

namespace dslam {
namespace synth {
namespace {

/// Depth [m] of the room's walls, floor or ceiling along pixel (u, v): an analytic ray / box exit.
double RoomDepth(const RoomParams& room, const PinholeCamera& cam, const Eigen::Isometry3d& T,
                 int u, int v) {
  const Eigen::Vector3d d =
      T.linear() * Eigen::Vector3d((u - cam.cx()) / cam.fx(), (v - cam.cy()) / cam.fy(), 1.0);
  double t = 1e9;
  for (int k = 0; k < 3; ++k) {
    const double bound = d[k] > 0 ? room.max_corner_m[k] : room.min_corner_m[k];
    if (std::abs(d[k]) > 1e-12) t = std::min(t, (bound - T.translation()[k]) / d[k]);
  }
  return t;  // d has unit optical-axis component, so t is the depth
}

TEST(SynthSequence, RoomDepthFollowsTheNoiseModel) {
  const SyntheticSequence sequence(MakeScenario("static_room", 3));
  const SyntheticFrame f = sequence.RenderFrame(10);
  const SensorParams& s = sequence.scenario().sensor;
  double sum = 0.0, sum_sq = 0.0;
  int on_room = 0, within_3_sigma = 0;
  for (int v = 0; v < f.mask.rows; ++v) {
    for (int u = 0; u < f.mask.cols; ++u) {
      const double measured = f.frame.depth_m.at<float>(v, u);
      if (measured <= 0.0) continue;
      const double truth =
          RoomDepth(sequence.scenario().room, *sequence.camera(), f.T_world_camera, u, v);
      const double sigma = s.depth_sigma_quadratic_per_m * truth * truth + s.depth_sigma_constant_m;
      if (std::abs(f.depth_true_m.at<float>(v, u) - truth) > 1e-5 * truth) continue;  // furniture
      const double r = (measured - truth) / sigma;
      ++on_room;
      within_3_sigma += std::abs(r) <= 3.0;
      sum += r;
      sum_sq += r * r;
    }
  }
  ASSERT_GT(on_room, static_cast<int>(f.mask.total() / 3));
  const double mean = sum / on_room, stddev = std::sqrt(sum_sq / on_room - mean * mean);
  EXPECT_LT(std::abs(mean), 0.05);
  EXPECT_NEAR(stddev, 1.0, 0.08);
  EXPECT_GT(within_3_sigma, 0.99 * on_room);
}

TEST(SynthSequence, DepthRangeAndEdgeDropouts) {
  const SyntheticSequence sequence(MakeScenario("walking", 1));
  const SyntheticFrame f = sequence.RenderFrame(30);
  int missing = 0;
  for (int v = 0; v < f.mask.rows; ++v) {
    for (int u = 0; u < f.mask.cols; ++u) {
      const float truth = f.depth_true_m.at<float>(v, u),
                  measured = f.frame.depth_m.at<float>(v, u);
      if (truth > 6.0f || truth < 0.3f) {
        EXPECT_EQ(measured, 0.0f);
      }
      missing += measured == 0.0f && truth >= 0.3f && truth <= 6.0f;
    }
  }
  EXPECT_GT(missing, 100);  // dropouts at the walkers' silhouettes
  EXPECT_LT(missing, static_cast<int>(f.mask.total() / 20));
}

/// ORB corners (refined to sub-pixel) matched between two noise-free frames of `walking` sit where
/// the ground-truth poses and noise-free depth reproject them: images agree with groundtruth.txt.
TEST(SynthSequence, GroundTruthReprojectsStaticCorners) {
  const SyntheticSequence sequence(MakeScenario("walking", 1));
  const SyntheticFrame fa = sequence.RenderFrame(20), fb = sequence.RenderFrame(26);
  cv::Mat grey_a, grey_b;
  cv::cvtColor(fa.colour_clean, grey_a, cv::COLOR_BGR2GRAY);
  cv::cvtColor(fb.colour_clean, grey_b, cv::COLOR_BGR2GRAY);
  const cv::Ptr<cv::ORB> orb =
      cv::ORB::create(1000, 1.2f, 1);  // one level: corners at full resolution
  std::vector<cv::KeyPoint> keys_a, keys_b;
  cv::Mat desc_a, desc_b;
  orb->detectAndCompute(grey_a, cv::noArray(), keys_a, desc_a);
  orb->detectAndCompute(grey_b, cv::noArray(), keys_b, desc_b);
  std::vector<cv::DMatch> matches;
  cv::BFMatcher(cv::NORM_HAMMING, true).match(desc_a, desc_b, matches);
  // Sub-pixel corner positions (FAST corners are whole pixels).
  std::vector<cv::Point2f> pts_a, pts_b;
  for (const cv::DMatch& m : matches) {
    pts_a.push_back(keys_a[m.queryIdx].pt);
    pts_b.push_back(keys_b[m.trainIdx].pt);
  }
  const cv::TermCriteria stop(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 0.01);
  cv::cornerSubPix(grey_a, pts_a, cv::Size(4, 4), cv::Size(-1, -1), stop);
  cv::cornerSubPix(grey_b, pts_b, cv::Size(4, 4), cv::Size(-1, -1), stop);
  const Eigen::Isometry3d T_b_a = fb.T_world_camera.inverse() * fa.T_world_camera;
  const PinholeCamera& cam = *sequence.camera();
  int static_matches = 0, within_pixel = 0;
  std::vector<double> errors;
  for (size_t i = 0; i < matches.size(); ++i) {
    const cv::Point2f& pa = pts_a[i];
    const cv::Point2f& pb = pts_b[i];
    if (matches[i].distance > 40) continue;
    const int u = cvRound(pa.x), v = cvRound(pa.y);
    const float depth = fa.depth_true_m.at<float>(v, u);
    if (fa.mask.at<uint16_t>(v, u) != 0 || depth <= 0.0f) continue;
    const Eigen::Vector2d uv_b =
        cam.Project(T_b_a * cam.BackProject(Eigen::Vector2d(pa.x, pa.y), depth));
    ++static_matches;
    errors.push_back((uv_b - Eigen::Vector2d(pb.x, pb.y)).norm());
    within_pixel += errors.back() <= 1.0;
  }
  // Gross mismatches say nothing about the poses; among the correspondences within 3 px the
  // reprojection error must be sub-pixel. Texture edges are not anti-aliased (one ray per pixel)
  // and many corners are on rotated shapes, so cornerSubPix is good to ~0.5 px, not better.
  std::vector<double> inliers;
  for (double e : errors) {
    if (e < 3.0) inliers.push_back(e);
  }
  ASSERT_GT(inliers.size(), 80u) << "of " << static_matches << " static matches";
  std::sort(inliers.begin(), inliers.end());
  EXPECT_LT(inliers[inliers.size() / 2], 0.6);
  EXPECT_GT(within_pixel, 0.7 * inliers.size()) << within_pixel << " of " << inliers.size();
}

TEST(SynthSequence, DeterministicInAnyOrderAndSeedDependent) {
  const SyntheticSequence first(MakeScenario("walking", 1)), second(MakeScenario("walking", 1));
  second.RenderFrame(7);  // rendering other frames first changes nothing
  const SyntheticFrame x = first.RenderFrame(5), y = second.RenderFrame(5);
  EXPECT_EQ(cv::norm(x.frame.colour, y.frame.colour, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(x.depth_units, y.depth_units, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(x.mask, y.mask, cv::NORM_INF), 0.0);
  const SyntheticFrame z = SyntheticSequence(MakeScenario("walking", 2)).RenderFrame(5);
  EXPECT_GT(cv::norm(x.frame.colour, z.frame.colour, cv::NORM_L1), 1e6);
  EXPECT_GT(cv::norm(x.depth_units, z.depth_units, cv::NORM_L1), 1e5);
}

std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A structured-light scene states no depth noise: like a real camera, the defaults model it.
TEST(SynthWriter, StructuredLightCameraStatesNoDepthNoise) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "dslam_synth_kinect_camera.yaml").string();
  WriteCameraYaml(path, MakeScenario("static_room_kinect", 1).sensor);
  const CameraYaml camera = LoadCameraYaml(path);
  EXPECT_FALSE(camera.depth_sigma_d_quadratic.has_value());
  EXPECT_FALSE(camera.depth_sigma_d_constant_m.has_value());
  DepthNoiseConfig noise;
  UseSensorDepthNoise(MakeScenario("static_room_kinect", 1).sensor, &noise);
  EXPECT_EQ(noise.sigma_d_quadratic, DepthNoiseConfig().sigma_d_quadratic);
  UseSensorDepthNoise(MakeScenario("static_room", 1).sensor, &noise);
  EXPECT_EQ(noise.sigma_d_quadratic,
            MakeScenario("static_room", 1).sensor.depth_sigma_quadratic_per_m);
}

TEST(SynthWriter, TumLayoutRoundTripsThroughTumDataset) {
  const std::string root = (std::filesystem::temp_directory_path() / "dslam_synth_test").string();
  std::filesystem::remove_all(root);
  const SyntheticSequence sequence(MakeScenario("slow_box", 1));
  const WriteSummary summary = WriteSequence(sequence, root + "/a", 3);
  WriteSequence(sequence, root + "/b", 3);
  EXPECT_EQ(summary.frames, 3);
  TumDataset dataset(root + "/a", "", 0.02);
  ASSERT_EQ(dataset.size(), 3u);
  EXPECT_DOUBLE_EQ(dataset.camera_yaml().camera->fx(), 525.0);
  EXPECT_DOUBLE_EQ(dataset.camera_yaml().depth_scale, 5000.0);
  // The Gaussian depth noise the renderer drew from, stated for the tracker.
  EXPECT_EQ(dataset.camera_yaml().depth_sigma_d_quadratic,
            sequence.scenario().sensor.depth_sigma_quadratic_per_m);
  EXPECT_EQ(dataset.camera_yaml().depth_sigma_d_constant_m,
            sequence.scenario().sensor.depth_sigma_constant_m);
  const SyntheticFrame f = sequence.RenderFrame(2);
  const RgbdFrame loaded = dataset.LoadFrame(2);
  EXPECT_EQ(loaded.stamp_s, f.frame.stamp_s);
  EXPECT_EQ(cv::norm(loaded.colour, f.frame.colour, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(loaded.depth_m, f.frame.depth_m, cv::NORM_INF), 0.0);
  const std::vector<StampedFile> masks = ReadFileList(root + "/a/mask.txt");
  ASSERT_EQ(masks.size(), 3u);
  const cv::Mat mask = cv::imread(root + "/a/" + masks[2].path, cv::IMREAD_ANYDEPTH);
  EXPECT_EQ(cv::norm(mask, f.mask, cv::NORM_INF), 0.0);
  const Trajectory gt = ReadTumTrajectory(dataset.groundtruth_path());
  ASSERT_EQ(gt.size(), 3u);
  EXPECT_EQ(gt[2].stamp_s, f.frame.stamp_s);
  EXPECT_LT((gt[2].T_world_camera.matrix() - f.T_world_camera.matrix()).norm(), 1e-5);
  for (const char* file : {"rgb.txt", "groundtruth.txt", "dynamic_coverage.txt", "mask.txt",
                           "camera.yaml", "depth/1000.066667.png", "rgb/1000.066667.png"}) {
    EXPECT_EQ(ReadAll(root + "/a/" + file), ReadAll(root + "/b/" + file)) << file;
  }
  std::filesystem::remove_all(root);
}

}  // namespace
}  // namespace synth
}  // namespace dslam
