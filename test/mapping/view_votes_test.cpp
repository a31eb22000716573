// VoteByViews: a view's rays measure, see through or say nothing of points, by direction and
// range from its camera.

#include <vector>

#include <gtest/gtest.h>

#include "dslam/mapping/view_votes.h"

namespace dslam {
namespace {

// A view from the origin of a wall x = 3 m (y, z in [-1, 1], points every 2 cm).
GridView WallView() {
  GridView view;
  for (double y = -1.0; y <= 1.0; y += 0.02) {
    for (double z = -1.0; z <= 1.0; z += 0.02) view.points_world.emplace_back(3.0f, y, z);
  }
  return view;
}

TEST(ViewVotes, PointsBeforeTheWallAreSeenThroughOnItMeasuredBehindItUnvoted) {
  const ViewVoteTolerance tolerance = ViewVoteTolerance::From(Config());
  // Misses beyond 5 cm + 2 % of the range, hits within it; measured within half a voxel (2.5 cm)
  // + 2 sigma_d.
  const std::vector<Eigen::Vector3f> points = {
      {2.0f, 0.1f, 0.0f},    // 1 m before the wall: seen through
      {3.0f, 0.1f, 0.0f},    // on the wall: measured
      {3.5f, 0.1f, 0.0f},    // behind the wall: hidden, no vote
      {0.0f, 0.0f, 3.0f},    // where the view has no ray: no vote
      {0.1f, 0.0f, 0.0f},    // nearer than the depth range's 0.3 m: no vote
      {2.0f, 0.6f, 0.0f}};   // its ray meets the wall 10 cm from its edge: seen through
  const std::vector<RayVotes> votes = VoteByViews(points, {WallView(), WallView()}, tolerance, 0.025);
  ASSERT_EQ(votes.size(), points.size());
  EXPECT_EQ(votes[0].misses, 2);
  EXPECT_EQ(votes[0].hits, 0);
  EXPECT_EQ(votes[1].hits, 2);
  EXPECT_EQ(votes[1].measured, 2);
  EXPECT_EQ(votes[1].misses, 0);
  for (int k : {2, 3, 4}) {
    EXPECT_EQ(votes[k].hits, 0) << k;
    EXPECT_EQ(votes[k].misses, 0) << k;
  }
  EXPECT_EQ(votes[5].misses, 2);
}

TEST(ViewVotes, APointOffTheSurfaceIsHitWithinTheMarginAndMeasuredOnlyWithinTheNoise) {
  ViewVoteTolerance tolerance = ViewVoteTolerance::From(Config());
  tolerance.depth_noise.sigma_d_quadratic = 0.0014;  // a good sensor: HitMargin(3) about 5 cm
  const float margin = static_cast<float>(tolerance.HitMargin(3.0));
  ASSERT_LT(1.5 * margin, tolerance.see_through.margin_m + 3.0 * tolerance.see_through.margin_ratio);
  const std::vector<Eigen::Vector3f> points = {{3.0f + 0.5f * margin, 0.0f, 0.0f},
                                               {3.0f + 1.5f * margin, 0.0f, 0.0f},
                                               {3.3f, 0.0f, 0.0f}};
  const std::vector<RayVotes> votes = VoteByViews(points, {WallView()}, tolerance, 0.025);
  EXPECT_EQ(votes[0].hits, 1);
  EXPECT_EQ(votes[0].measured, 1);
  EXPECT_EQ(votes[1].hits, 1);  // within the see-through margin of the wall
  EXPECT_EQ(votes[1].measured, 0);  // but not what the wall's depth could have measured
  EXPECT_EQ(votes[2].hits + votes[2].measured + votes[2].misses, 0);  // hidden behind the wall
}

}  // namespace
}  // namespace dslam
