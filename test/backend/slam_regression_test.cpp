// Whole-trajectory regression tests of Slam (front end and back end, synchronous) on short
// synthetic sequences rendered in-process, against ground truth and against the front end alone.
// Tolerances are measured values with margin (comment at each bound).
#include <gtest/gtest.h>

#include "dslam/backend/slam.h"
#include "support/ate.h"
#include "support/rendered_sequence.h"

namespace dslam {
namespace {

using Rendered = test::RenderedSequence;
using test::RenderSequence;

struct RunResult {
  double ate_m = 0.0, refined_ate_m = 0.0;
  int with_pose = 0, backend_runs = 0, rejected = 0;
};

RunResult RunSlam(const Rendered& rendered, bool backend) {
  Config config;
  config.backend.enabled = backend;
  Slam slam(config);
  RunResult out;
  const Trajectory estimated =
      test::TrackAll(&slam, rendered.frames, [&out](size_t, const FrameResult& result) {
        out.with_pose += result.has_pose;
        out.backend_runs += result.backend.ba.ran;
        out.rejected += result.backend.ba.rejected;
      });
  out.ate_m = test::AteRmse(estimated, rendered.groundtruth);
  out.refined_ate_m = test::AteRmse(slam.RefinedPoses(), rendered.groundtruth);
  return out;
}

TEST(SlamRegression, BackEndKeepsStaticRoomAccurate) {
  const Rendered rendered = RenderSequence("static_room", 90);
  const RunResult on = RunSlam(rendered, true);
  const RunResult off = RunSlam(rendered, false);
  EXPECT_EQ(on.with_pose, 90);
  EXPECT_GE(on.backend_runs, 5);  // a keyframe every 3-10 frames
  EXPECT_EQ(on.rejected, 0);      // nothing moves: every solution is applied
  EXPECT_EQ(off.backend_runs, 0);
  EXPECT_LT(on.ate_m, 0.006);  // measured ~2 mm over 300 frames
  EXPECT_LT(on.ate_m, 1.5 * off.ate_m + 0.001);
  EXPECT_LT(on.refined_ate_m, 1.5 * off.ate_m + 0.001);
}

TEST(SlamRegression, BackEndOffIsTheFrontEnd) {
  const Rendered rendered = RenderSequence("walking", 45);
  Config config;
  config.backend.enabled = false;
  Slam slam(config);
  Odometry odometry(config);
  for (const RgbdFrame& frame : rendered.frames) {
    const FrameResult a = slam.ProcessFrame(frame);
    const FrameResult b = odometry.ProcessFrame(frame);
    ASSERT_EQ(a.has_pose, b.has_pose);
    if (a.has_pose) {
      EXPECT_TRUE(a.T_world_camera.isApprox(b.T_world_camera, 0.0));
    }
  }
}

}  // namespace
}  // namespace dslam
