// Tests of the moving-object truth (object_truth.h): analytic velocities against known motions and
// central differences, centroids of hand-made and rendered frames, and the written files
// (objects.txt, depth_true/) read back by the measurements of part eval.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include "dslam/eval/map_metrics.h"
#include "dslam/eval/object_metrics.h"
#include "dslam/io/dataset_io.h"
#include "dslam/io/trajectory_io.h"
#include "dslam/synth/object_truth.h"
#include "dslam/synth/writer.h"

namespace dslam {
namespace synth {
namespace {

constexpr double kStep_s = 1e-4;  ///< [s] half step of the central differences

TEST(ObjectTruth, BoxVelocityIsKnownAndTheCentreDerivative) {
  MovingBoxParams box;
  box.start_m = {0.0, 0.0, 0.25};
  box.end_m = {1.2, 0.5, 0.25};  // 1.3 m away
  box.speed_mps = 0.1;
  const Eigen::Vector3d out = Eigen::Vector3d(1.2, 0.5, 0.0) / 1.3;
  EXPECT_TRUE(MovingBoxCentreAt(box, 2.0).isApprox(box.start_m + 0.2 * out, 1e-12));
  EXPECT_TRUE(MovingBoxVelocityAt(box, 2.0).isApprox(0.1 * out, 1e-12));
  EXPECT_TRUE(MovingBoxVelocityAt(box, 15.0).isApprox(-0.1 * out, 1e-12));  // on the way back
  EXPECT_TRUE(MovingBoxVelocityAt(box, 27.0).isApprox(0.1 * out, 1e-12));   // out again
  for (double t : {0.5, 7.0, 12.9, 13.1, 20.0, 25.9}) {
    const Eigen::Vector3d difference =
        (MovingBoxCentreAt(box, t + kStep_s) - MovingBoxCentreAt(box, t - kStep_s)) / (2 * kStep_s);
    EXPECT_LT((difference - MovingBoxVelocityAt(box, t)).norm(), 1e-8) << "t = " << t;
  }
  box.end_m = box.start_m;
  EXPECT_EQ(MovingBoxVelocityAt(box, 3.0), Eigen::Vector3d::Zero());
}

TEST(ObjectTruth, WalkerVelocityIsTheSpeedAlongItsPathAndZeroWhilePausing) {
  WalkerParams w;
  w.path_m = {{0.0, 0.0}, {2.0, 0.0}, {2.0, 2.0}, {0.0, 2.0}};
  w.dwell_s = {0.0, 1.0, 0.0, 0.0};  // pauses 1 s at (2, 0)
  w.speed_mps = 0.8;
  EXPECT_TRUE(WalkerVelocityAt(w, 1.0).isApprox(Eigen::Vector3d(0.8, 0.0, 0.0)));
  EXPECT_EQ(WalkerVelocityAt(w, 3.0), Eigen::Vector3d::Zero());  // arrived at 2.5 s
  EXPECT_TRUE(WalkerVelocityAt(w, 4.0).isApprox(Eigen::Vector3d(0.0, 0.8, 0.0)));
  EXPECT_TRUE(WalkerVelocityAt(w, 9.0).isApprox(Eigen::Vector3d(0.0, -0.8, 0.0)));
  for (double t : {0.3, 2.8, 4.4, 7.1, 8.6, 12.0}) {  // away from the waypoints
    const Eigen::Vector2d difference =
        (WalkerStateAt(w, t + kStep_s).position_m - WalkerStateAt(w, t - kStep_s).position_m) /
        (2 * kStep_s);
    EXPECT_LT((difference - WalkerVelocityAt(w, t).head<2>()).norm(), 1e-8) << "t = " << t;
  }
}

TEST(ObjectTruth, CentroidAndShareOfAHandMadeFrame) {
  const SyntheticSequence sequence(MakeScenario("slow_box", 1));  // box ids 1 and 2
  SyntheticFrame frame;
  frame.index = 30;  // t = 1 s
  frame.mask = cv::Mat(480, 640, CV_16UC1, cv::Scalar(0));
  frame.depth_true_m = cv::Mat(480, 640, CV_32FC1, cv::Scalar(3.0f));
  frame.mask(cv::Rect(100, 50, 100, 100)).setTo(1);
  frame.depth_true_m(cv::Rect(100, 50, 100, 100)).setTo(2.0f);
  frame.mask.at<uint16_t>(239, 319) = 2;
  frame.T_world_camera.linear() =
      Eigen::AngleAxisd(0.5, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  frame.T_world_camera.translation() = Eigen::Vector3d(1.0, 2.0, 3.0);
  const std::vector<ObjectTruth> objects = VisibleObjects(sequence, frame);
  ASSERT_EQ(objects.size(), 2u);
  EXPECT_EQ(objects[0].id, 1);
  EXPECT_EQ(objects[0].pixels, 10000);
  EXPECT_DOUBLE_EQ(objects[0].pixel_share, 10000.0 / (640 * 480));
  // Mean pixel (149.5, 99.5) at 2 m.
  const Eigen::Vector3d centre(2.0 * (149.5 - 319.5) / 525.0, 2.0 * (99.5 - 239.5) / 525.0, 2.0);
  EXPECT_LT((objects[0].centroid_world_m - frame.T_world_camera * centre).norm(), 1e-9);
  EXPECT_TRUE(objects[0].velocity_world_mps.isApprox(Eigen::Vector3d(0.09, 0.0, 0.0)));
  EXPECT_EQ(objects[1].id, 2);
  EXPECT_EQ(objects[1].pixels, 1);
  const Eigen::Vector3d pixel(-0.5 * 3.0 / 525.0, -0.5 * 3.0 / 525.0, 3.0);
  EXPECT_LT((objects[1].centroid_world_m - frame.T_world_camera * pixel).norm(), 1e-9);
  EXPECT_THROW(ObjectVelocityAt(sequence.scenario(), 3, 1.0), std::out_of_range);
  EXPECT_THROW(ObjectVelocityAt(sequence.scenario(), 0, 1.0), std::out_of_range);
}

TEST(ObjectTruth, RenderedBoxCentroidLiesInTheBoxAndFollowsIt) {
  // slow_box: box 1 (0.6 m cube) slides along +x at 0.09 m/s, without turning, for 22 s; seen
  // from the static camera (2 mm jitter).
  Scenario scenario = MakeScenario("slow_box", 1);
  scenario.camera.kind = CameraMotionKind::kStatic;
  const SyntheticSequence sequence(scenario);
  const MovingBoxParams& box = sequence.scenario().boxes[0];
  const Eigen::Vector3d moved = MovingBoxCentreAt(box, 3.0) - MovingBoxCentreAt(box, 1.0);
  EXPECT_NEAR(moved.x(), 0.18, 1e-12);
  Eigen::Vector3d centroid[2];
  for (int k = 0; k < 2; ++k) {
    const double t = 1.0 + 2.0 * k;
    const std::vector<ObjectTruth> truth =
        VisibleObjects(sequence, sequence.RenderFrame(static_cast<int>(t * 30.0)));
    ASSERT_FALSE(truth.empty());
    ASSERT_EQ(truth[0].id, 1);
    EXPECT_TRUE(truth[0].velocity_world_mps.isApprox(Eigen::Vector3d(0.09, 0.0, 0.0)));
    // The mean of points on the box's surface lies in the (convex) box.
    centroid[k] = truth[0].centroid_world_m;
    const Eigen::Vector3d local = centroid[k] - MovingBoxCentreAt(box, t);
    EXPECT_LE(local.cwiseAbs().maxCoeff(), 0.3 + 1e-5) << local.transpose();
  }
  // The visible faces change with the view (less of the right face as the box nears the optical
  // axis), so the centroid follows the body's 0.18 m only roughly: measured 0.144 m in x.
  EXPECT_LT((centroid[1] - centroid[0] - moved).norm(), 0.05);
}

TEST(ObjectTruth, WalkersMoveAtTheirSpeedOrPause) {
  const SyntheticSequence sequence(MakeScenario("walking", 1));
  int walking = 0, pausing = 0;
  for (int index = 0; index < 300; index += 15) {
    for (const ObjectTruth& o : VisibleObjects(sequence, sequence.RenderFrame(index))) {
      const double speed = o.velocity_world_mps.norm();
      EXPECT_TRUE(std::abs(speed - 1.0) < 1e-9 || speed == 0.0) << speed;
      EXPECT_EQ(o.velocity_world_mps.z(), 0.0);
      EXPECT_GT(o.centroid_world_m.z(), 0.0);   // on the body: between the floor
      EXPECT_LT(o.centroid_world_m.z(), 1.75);  // and the top of the head
      walking += speed > 0.0;
      pausing += speed == 0.0;
    }
  }
  EXPECT_GT(walking, 10);
  EXPECT_GT(pausing, 0);
}

}  // namespace
}  // namespace synth
}  // namespace dslam
