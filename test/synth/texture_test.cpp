// Tests of the procedural textures: ORB matches between frames are unambiguous (few false matches
// on static surfaces), and moving people carry corners too.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "dslam/synth/sequence.h"
#include "dslam/synth/texture.h"

namespace dslam {
namespace synth {
namespace {

/// ORB matches between two frames whose first keypoint is on a static, still-visible surface.
struct MatchCount {
  int static_matches = 0;  ///< ratio-test matches with a static, unoccluded keypoint in frame a
  int correct = 0;         ///< of those, matches within 3 px of the ground-truth prediction
  double walker_density_ratio = 0.0;  ///< keypoints per pixel on moving objects / on static ones
  int walker_keypoints = 0;           ///< keypoints of frame a on moving objects
};

/// Extracts cv::ORB (1000 features) in the noisy colour of frames `a` and `b`, matches by brute
/// force with the 0.8 ratio test and checks each static match against the position predicted by
/// the noise-free depth and the ground-truth poses.
MatchCount CountCorrectMatches(const SyntheticSequence& sequence, int a, int b) {
  const SyntheticFrame fa = sequence.RenderFrame(a), fb = sequence.RenderFrame(b);
  cv::Mat grey_a, grey_b;
  cv::cvtColor(fa.frame.colour, grey_a, cv::COLOR_BGR2GRAY);
  cv::cvtColor(fb.frame.colour, grey_b, cv::COLOR_BGR2GRAY);
  const cv::Ptr<cv::ORB> orb = cv::ORB::create(1000);
  std::vector<cv::KeyPoint> keys_a, keys_b;
  cv::Mat desc_a, desc_b;
  orb->detectAndCompute(grey_a, cv::noArray(), keys_a, desc_a);
  orb->detectAndCompute(grey_b, cv::noArray(), keys_b, desc_b);
  std::vector<std::vector<cv::DMatch>> knn;
  cv::BFMatcher(cv::NORM_HAMMING).knnMatch(desc_a, desc_b, knn, 2);
  const Eigen::Isometry3d T_b_a = fb.T_world_camera.inverse() * fa.T_world_camera;
  const PinholeCamera& cam = *sequence.camera();
  MatchCount count;
  for (const cv::KeyPoint& k : keys_a) {
    count.walker_keypoints += fa.mask.at<uint16_t>(cvRound(k.pt.y), cvRound(k.pt.x)) != 0;
  }
  const double walker_pixels = cv::countNonZero(fa.mask);
  const double static_pixels = static_cast<double>(fa.mask.total()) - walker_pixels;
  count.walker_density_ratio = (count.walker_keypoints / walker_pixels) /
                               ((keys_a.size() - count.walker_keypoints) / static_pixels);
  for (const std::vector<cv::DMatch>& m : knn) {
    if (m.size() < 2 || m[0].distance >= 0.8f * m[1].distance) continue;
    const cv::Point2f& pa = keys_a[m[0].queryIdx].pt;
    const cv::Point2f& pb = keys_b[m[0].trainIdx].pt;
    const int ua = cvRound(pa.x), va = cvRound(pa.y);
    const float depth = fa.depth_true_m.at<float>(va, ua);
    if (fa.mask.at<uint16_t>(va, ua) != 0 || depth <= 0.0f) continue;
    const Eigen::Vector3d p_b = T_b_a * cam.BackProject(Eigen::Vector2d(pa.x, pa.y), depth);
    const Eigen::Vector2d predicted = cam.Project(p_b);
    const int ub = cvRound(predicted.x()), vb = cvRound(predicted.y());
    if (ub < 0 || vb < 0 || ub >= fb.mask.cols || vb >= fb.mask.rows) continue;
    // Hidden in frame b (behind a walker) or off the surface: no correct match exists.
    if (fb.mask.at<uint16_t>(vb, ub) != 0) continue;
    if (std::abs(fb.depth_true_m.at<float>(vb, ub) - p_b.z()) > 0.03 * p_b.z()) continue;
    ++count.static_matches;
    count.correct += (predicted - Eigen::Vector2d(pb.x, pb.y)).norm() <= 3.0;
  }
  return count;
}

TEST(SynthTexture, OrbMatchesOnStaticSurfacesAreCorrect) {
  const SyntheticSequence sequence(MakeScenario("walking", 1));
  int total = 0, correct = 0;
  for (int a : {20, 100, 200}) {
    const MatchCount c = CountCorrectMatches(sequence, a, a + 6);
    std::printf(
        "frames %d-%d: %d of %d static matches correct (%.1f %%); %d keypoints on walkers, "
        "density ratio walker / static %.2f\n",
        a, a + 6, c.correct, c.static_matches, 100.0 * c.correct / c.static_matches,
        c.walker_keypoints, c.walker_density_ratio);
    ASSERT_GT(c.static_matches, 80);
    EXPECT_GT(c.walker_density_ratio, 0.5);  // people carry corners (needed to see them move)
    EXPECT_GE(c.correct, 0.85 * c.static_matches);
    total += c.static_matches;
    correct += c.correct;
  }
  EXPECT_GE(correct, 0.88 * total);
}

}  // namespace
}  // namespace synth
}  // namespace dslam
