// ObjectTracker on hand-made observation sequences: constant-velocity movers with seeded
// centroid noise, crossing movers of different colours, gaps and stamps going backwards.
#include "dslam/mapping/object_tracker.h"

#include <map>
#include <random>

#include <gtest/gtest.h>

namespace dslam {
namespace {

constexpr double kFps = 30.0;

ObjectObservation Observe(const Eigen::Vector3d& p, const Eigen::Vector3d& colour) {
  ObjectObservation o;
  o.centroid_world = p;
  o.colour = colour;
  o.extent = Eigen::Vector3d(0.5, 0.3, 1.7);
  o.points = 20;
  return o;
}

TEST(ObjectTracker, ConstantVelocityMoverKeepsItsIdAndItsVelocityIsFound) {
  ObjectTracker tracker{ObjectsConfig()};
  std::mt19937 rng(42);
  std::normal_distribution<double> noise(0.0, 0.03);
  const Eigen::Vector3d start(1.0, 0.0, 3.0), velocity(1.2, 0.0, -0.3);
  std::vector<TrackedObject> objects;
  for (int i = 0; i < 90; ++i) {
    const double t = i / kFps;
    const Eigen::Vector3d p =
        start + velocity * t + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    objects = tracker.Update(100.0 + t, {Observe(p, Eigen::Vector3d(0.2, 0.4, 0.6))});
    if (i < ObjectsConfig().min_hits - 1) {
      EXPECT_TRUE(objects.empty()) << i;
    }
    if (i >= ObjectsConfig().min_hits - 1) {
      ASSERT_EQ(objects.size(), 1u) << i;
      EXPECT_EQ(objects[0].id, 1);
    }
  }
  EXPECT_LT((objects[0].velocity_world - velocity).norm(), 0.15);
  EXPECT_LT((objects[0].position_world - (start + velocity * 89 / kFps)).norm(), 0.05);
  EXPECT_NEAR(objects[0].age_s, 89 / kFps, 1e-9);
  EXPECT_EQ(objects[0].extent, Eigen::Vector3d(0.5, 0.3, 1.7));
}

TEST(ObjectTracker, CrossingMoversOfDifferentColoursKeepTheirIds) {
  ObjectTracker tracker{ObjectsConfig()};
  const Eigen::Vector3d red(0, 0, 1), blue(1, 0, 0);
  std::map<int, double> x_of_id;  // id -> sign of the x velocity it had
  for (int i = 0; i < 60; ++i) {
    const double t = i / kFps;
    // They pass 0.2 m apart (in y) at t = 1 s: position alone would be ambiguous there.
    const Eigen::Vector3d a(-1.0 + t, 0.0, 3.0), b(1.0 - t, 0.2, 3.0);
    for (const TrackedObject& o : tracker.Update(t, {Observe(a, red), Observe(b, blue)})) {
      if (i > 45) x_of_id[o.id] = o.velocity_world.x();
    }
  }
  ASSERT_EQ(x_of_id.size(), 2u);
  EXPECT_GT(x_of_id[1], 0.5);
  EXPECT_LT(x_of_id[2], -0.5);
}

TEST(ObjectTracker, TracksUnseenTooLongAreDroppedAndNewOnesGetNewIds) {
  ObjectsConfig config;
  ObjectTracker tracker{config};
  const Eigen::Vector3d grey(0.5, 0.5, 0.5);
  for (int i = 0; i < 10; ++i) tracker.Update(i / kFps, {Observe({0, 0, 2}, grey)});
  EXPECT_EQ(tracker.track_count(), 1);
  // Frames without observations: kept while unseen for at most max_unseen_s.
  double t = 9 / kFps;
  while (t < 9 / kFps + config.max_unseen_s - 0.05) {
    t += 1 / kFps;
    EXPECT_TRUE(tracker.Update(t, {}).empty());
  }
  EXPECT_EQ(tracker.track_count(), 1);
  t += 0.1;
  tracker.Update(t, {});
  EXPECT_EQ(tracker.track_count(), 0);
  std::vector<TrackedObject> objects;
  for (int i = 0; i < config.min_hits; ++i) {
    t += 1 / kFps;
    objects = tracker.Update(t, {Observe({0, 0, 2}, grey)});
  }
  ASSERT_EQ(objects.size(), 1u);
  EXPECT_EQ(objects[0].id, 2);
}

TEST(ObjectTracker, StampGoingBackwardsClearsTheTracks) {
  ObjectTracker tracker{ObjectsConfig()};
  const Eigen::Vector3d grey(0.5, 0.5, 0.5);
  for (int i = 0; i < 5; ++i) tracker.Update(10.0 + i / kFps, {Observe({0, 0, 2}, grey)});
  EXPECT_EQ(tracker.track_count(), 1);
  EXPECT_TRUE(tracker.Update(5.0, {Observe({0, 0, 2}, grey)}).empty());
  EXPECT_EQ(tracker.track_count(), 1);  // the new track, not yet reported
}

TEST(ObjectTracker, FarObservationStartsASecondTrackInsteadOfJumping) {
  ObjectTracker tracker{ObjectsConfig()};
  const Eigen::Vector3d grey(0.5, 0.5, 0.5);
  for (int i = 0; i < 5; ++i) tracker.Update(i / kFps, {Observe({0, 0, 2}, grey)});
  tracker.Update(5 / kFps, {Observe({2, 0, 2}, grey)});
  EXPECT_EQ(tracker.track_count(), 2);
}

TEST(ObservationsFromMask, SmallRegionsAreLeftOut) {
  DynamicMask mask;
  DynamicRegion big, few_points, few_cells;
  big.points.assign(10, 0);
  big.cells = 100;
  big.min_world = Eigen::Vector3d(0, 0, 0);
  big.max_world = Eigen::Vector3d(0.4, 1.8, 0.3);
  few_points = big;
  few_points.points.assign(2, 0);
  few_cells = big;
  few_cells.cells = 3;
  mask.regions = {big, few_points, few_cells};
  const std::vector<ObjectObservation> observations = ObservationsFromMask(mask, ObjectsConfig());
  ASSERT_EQ(observations.size(), 1u);
  EXPECT_EQ(observations[0].extent, Eigen::Vector3d(0.4, 1.8, 0.3));
  EXPECT_EQ(observations[0].points, 10);
}

}  // namespace
}  // namespace dslam
