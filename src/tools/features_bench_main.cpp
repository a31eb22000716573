// dslam_features_bench: median runtime of ORB extraction (640x480, random-block texture with depth)
// and of the motion-only BA with 300 RGB-D correspondences (20% outliers), once per PoseSolver
// (levenberg_marquardt, ceres; interleaved, so that load changes hit both alike). OpenCV's thread
// count (feature detection runs in parallel) is the second argument; the BA is single-threaded.
// Usage: dslam_features_bench [repetitions=30] [threads=1]

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <opencv2/imgproc.hpp>

#include "dslam/core/stopwatch.h"
#include "dslam/eval/quantile.h"
#include "dslam/features/features.h"
#include "dslam/tracking/pose_optimizer.h"

namespace {

dslam::RgbdFrame TexturedFrame(std::mt19937* rng) {
  std::uniform_int_distribution<int> grey(0, 255);
  cv::Mat small(61, 81, CV_8UC1);
  for (int r = 0; r < small.rows; ++r) {
    for (int c = 0; c < small.cols; ++c) small.at<uchar>(r, c) = static_cast<uchar>(grey(*rng));
  }
  cv::Mat big;
  cv::resize(small, big, cv::Size(), 8, 8, cv::INTER_NEAREST);
  dslam::RgbdFrame frame;
  cv::Mat grey_image;
  cv::GaussianBlur(big(cv::Rect(0, 0, 640, 480)), grey_image, cv::Size(3, 3), 0.8);
  cv::cvtColor(grey_image, frame.colour, cv::COLOR_GRAY2BGR);
  frame.depth_m = cv::Mat(480, 640, CV_32FC1, cv::Scalar(2.0));
  frame.camera = std::make_shared<dslam::PinholeCamera>(640, 480, 525.0, 525.0, 319.5, 239.5);
  return frame;
}

std::vector<dslam::PoseObservation> Observations(const dslam::PinholeCamera& camera,
                                                 const Eigen::Isometry3d& T_cw, std::mt19937* rng) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  const dslam::DepthNoiseConfig noise;
  std::vector<dslam::PoseObservation> obs;
  for (int i = 0; i < 300; ++i) {
    const Eigen::Vector2d uv(20 + 600 * uni(*rng), 20 + 440 * uni(*rng));
    const double d = 1.0 + 3.0 * uni(*rng);
    const double s = dslam::DepthSigma(d, noise);
    dslam::PointMeasurement m;
    m.covariance = dslam::PointCovariance(uv, {d, s * s}, 1.0, camera);
    const Eigen::Vector3d white(normal(*rng), normal(*rng), normal(*rng));
    m.y_camera = camera.BackProject(uv, d) + m.covariance.llt().matrixL() * white;
    if (uni(*rng) < 0.2) m.y_camera += Eigen::Vector3d(0.3, -0.2, 0.4);
    obs.push_back(dslam::PoseObservation::WithDepth(T_cw.inverse() * camera.BackProject(uv, d), m));
  }
  return obs;
}

}  // namespace

int main(int argc, char** argv) {
  const int reps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 30;
  const int threads = argc > 2 ? std::max(1, std::atoi(argv[2])) : 1;
  cv::setNumThreads(threads);
  std::mt19937 rng(1);
  const dslam::RgbdFrame frame = TexturedFrame(&rng);
  std::vector<double> extract_ms;
  size_t num_features = 0;
  for (int i = 0; i < reps; ++i) {
    const dslam::Stopwatch watch;
    num_features = dslam::ExtractFeatures(frame, {}, {}).features.size();
    extract_ms.push_back(watch.ElapsedMs());
  }
  const Eigen::Isometry3d T_cw(Eigen::Translation3d(0.1, 0.0, 0.2) *
                               Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()));
  const auto obs = Observations(*frame.camera, T_cw, &rng);
  const Eigen::Isometry3d guess = Eigen::Translation3d(0.03, 0.02, -0.03) * T_cw;
  const std::vector<std::string> solvers = {"levenberg_marquardt", "ceres"};
  const dslam::PoseSolver kinds[] = {dslam::PoseSolver::kLevenbergMarquardt,
                                     dslam::PoseSolver::kCeres};
  std::vector<std::vector<double>> ba_ms(solvers.size());
  std::vector<int> inliers(solvers.size(), 0);
  for (int i = 0; i < reps; ++i) {
    for (size_t k = 0; k < solvers.size(); ++k) {
      const dslam::Stopwatch watch;
      inliers[k] =
          dslam::EstimatePose(obs, guess, *frame.camera, dslam::PoseConfig(), nullptr, kinds[k])
              .num_inliers;
      ba_ms[k].push_back(watch.ElapsedMs());
    }
  }
  std::printf("ORB extraction 640x480: %zu features, median %.2f ms over %d runs (%d thread%s)\n",
              num_features, dslam::Median(extract_ms), reps, threads, threads == 1 ? "" : "s");
  for (size_t k = 0; k < solvers.size(); ++k) {
    std::printf(
        "motion-only BA (%s), 300 correspondences (%d inliers): median %.3f ms over %d runs\n",
        solvers[k].c_str(), inliers[k], dslam::Median(ba_ms[k]), reps);
  }
  return 0;
}
