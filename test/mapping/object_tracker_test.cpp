// ObjectTracker on hand-made observation sequences: constant-velocity movers with seeded
// centroid noise, crossing movers of different colours, gaps and stamps going backwards.
#include "dslam/mapping/object_tracker.h"

#include <cmath>
#include <deque>
#include <map>
#include <random>

#include <gtest/gtest.h>

namespace dslam {
namespace {

constexpr double kFps = 30.0;

/// An observation at `p` whose points move at `velocity` [m/s] (measured over both baselines).
ObjectObservation Observe(const Eigen::Vector3d& p, const Eigen::Vector3d& colour,
                          const Eigen::Vector3d& velocity = Eigen::Vector3d(0.5, 0.0, 0.0)) {
  ObjectObservation o;
  o.centroid_world = p;
  o.colour = colour;
  o.velocity_world = velocity;
  o.has_velocity = true;
  o.motion_speed_mps = velocity.norm();
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
    objects = tracker.Update(100.0 + t, {Observe(p, Eigen::Vector3d(0.2, 0.4, 0.6), velocity)});
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
    const Eigen::Vector3d east(1, 0, 0), west(-1, 0, 0);
    for (const TrackedObject& o :
         tracker.Update(t, {Observe(a, red, east), Observe(b, blue, west)})) {
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
  // Frames without observations: reported (predicted) for coast_s, kept while unseen for at
  // most max_unseen_s.
  double t = 9 / kFps;
  while (t < 9 / kFps + config.max_unseen_s - 0.05) {
    t += 1 / kFps;
    const bool coasting = t - 9 / kFps <= config.coast_s;
    EXPECT_EQ(tracker.Update(t, {}).size(), coasting ? 1u : 0u) << t;
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

TEST(ObjectTracker, AThingWhosePointsNeverMoveIsNeverReported) {
  // A static surface whose points the front end left unmarked: observed in every frame, its
  // centroid jittering by region changes, its points still.
  ObjectTracker tracker{ObjectsConfig()};
  std::mt19937 rng(3);
  std::normal_distribution<double> jitter(0.0, 0.1);
  for (int i = 0; i < 60; ++i) {
    const Eigen::Vector3d p(1.0 + jitter(rng), jitter(rng), 4.0);
    EXPECT_TRUE(tracker
                    .Update(i / kFps, {Observe(p, Eigen::Vector3d(0.5, 0.5, 0.5),
                                               Eigen::Vector3d(0.05, 0.0, 0.0))})
                    .empty());
  }
  EXPECT_EQ(tracker.track_count(), 1);
}

TEST(ObjectTracker, PointSpeedsWithinTheirDepthNoiseAreNoMotion) {
  // The same 0.3 m/s point speed, its depth-noise sigma 0.2 m/s (never reported) or 0.05 m/s
  // (reported after min_hits observations).
  for (const double sigma : {0.2, 0.05}) {
    ObjectTracker tracker{ObjectsConfig()};
    std::vector<TrackedObject> objects;
    for (int i = 0; i < 30; ++i) {
      ObjectObservation o =
          Observe({1.0, 0.0, 4.0}, Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d(0.3, 0.0, 0.0));
      o.motion_sigma_mps = sigma;
      objects = tracker.Update(i / kFps, {o});
      if (sigma < 0.1 && i + 1 >= ObjectsConfig().min_hits) {
        EXPECT_EQ(objects.size(), 1u) << i;
      }
    }
    EXPECT_EQ(objects.size(), sigma < 0.1 ? 1u : 0u);
  }
}

TEST(ObjectTracker, AWalkerWhoStopsStaysReportedWithZeroVelocity) {
  ObjectTracker tracker{ObjectsConfig()};
  const Eigen::Vector3d grey(0.5, 0.5, 0.5);
  Eigen::Vector3d p(0.0, 0.0, 2.0);
  std::vector<TrackedObject> objects;
  for (int i = 0; i < 90; ++i) {
    const Eigen::Vector3d v = i < 30 ? Eigen::Vector3d(1.0, 0.0, 0.0) : Eigen::Vector3d::Zero();
    p += v / kFps;
    objects = tracker.Update(i / kFps, {Observe(p, grey, v)});
  }
  ASSERT_EQ(objects.size(), 1u);
  EXPECT_LT(objects[0].velocity_world.norm(), 0.05);
}

/// [m/s] velocity error of a walker's track 3 frames after it turns a corner (from +x to -y at
/// 1 m/s; observed velocities with seeded noise of sigma 0.15 m/s) under `config`.
double ErrorThreeFramesAfterACorner(const ObjectsConfig& config) {
  ObjectTracker tracker{config};
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.15);
  const Eigen::Vector3d grey(0.5, 0.5, 0.5);
  Eigen::Vector3d p(0.0, 0.0, 2.0), v;
  std::vector<TrackedObject> objects;
  for (int i = 0; i < 63; ++i) {
    v = i < 60 ? Eigen::Vector3d(1.0, 0.0, 0.0) : Eigen::Vector3d(0.0, -1.0, 0.0);
    p += v / kFps;
    const Eigen::Vector3d measured = v + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    objects = tracker.Update(i / kFps, {Observe(p, grey, measured)});
  }
  return objects.size() == 1 ? (objects[0].velocity_world - v).norm() : 1e9;
}

TEST(ObjectTracker, AWalkerTurningACornerIsFollowedWithinThreeFrames) {
  ObjectsConfig without_reset;
  without_reset.maneuver_chi2 = 0.0;
  EXPECT_LT(ErrorThreeFramesAfterACorner(ObjectsConfig()), 0.3);
  EXPECT_GT(ErrorThreeFramesAfterACorner(without_reset), 0.6);
}

TEST(ObjectTracker, PredictedPositionsAreThoseOfMovedTracksAtTheStamp) {
  ObjectTracker tracker{ObjectsConfig()};
  const Eigen::Vector3d grey(0.5, 0.5, 0.5), v(1.0, 0.0, 0.0);
  Eigen::Vector3d p(0.0, 0.0, 2.0);
  EXPECT_TRUE(tracker.PredictedPositions(0.0).empty());
  for (int i = 0; i < 30; ++i) {
    p += v / kFps;
    // A second thing that never moves is never predicted.
    tracker.Update(i / kFps, {Observe(p, grey, v), Observe({3.0, 0.0, 2.0}, grey, {0, 0, 0})});
  }
  const double last = 29 / kFps;
  const std::vector<Eigen::Vector3d> predicted = tracker.PredictedPositions(last + 0.1);
  ASSERT_EQ(predicted.size(), 1u);
  EXPECT_LT((predicted[0] - (p + 0.1 * v)).norm(), 0.02);
  // A stamp that would clear the tracks predicts nothing.
  EXPECT_TRUE(tracker.PredictedPositions(last).empty());
  EXPECT_TRUE(tracker.PredictedPositions(last + ObjectsConfig().max_unseen_s + 0.1).empty());
}

TEST(ObservationsFromMask, PointVelocitiesAreMediansOverTheBaselineWithoutJumps) {
  // Ten points moving at (1, 0, 0.5) m/s seen in the last frames, one of them re-matched 3 m away
  // (a jump, not a motion), and the frame 0.5 s ago beyond both baselines.
  ObjectsConfig config;
  const Eigen::Vector3d velocity(1.0, 0.0, 0.5);
  DynamicMask mask;
  DynamicRegion region;
  region.cells = 500;
  std::deque<PointPositions> history(3);
  history[0].stamp_s = 9.5;
  history[1].stamp_s = 10.0 - 0.2;
  history[2].stamp_s = 10.0 - 1.0 / kFps;
  for (int k = 0; k < 10; ++k) {
    const Eigen::Vector3d p_now(0.1 * k, 0.05 * k, 2.0);
    region.points.push_back(k);
    region.points_world.push_back(k == 0 ? p_now + Eigen::Vector3d(0, 0, 3) : p_now);
    history[0].by_id[k] = p_now - 0.5 * Eigen::Vector3d(9, 9, 9);
    history[1].by_id[k] = p_now - 0.2 * velocity;
    history[2].by_id[k] = p_now - velocity / kFps;
  }
  region.centroid_world = Eigen::Vector3d(1.0, 2.0, 2.0);
  mask.regions = {region};
  const std::vector<ObjectObservation> observations =
      ObservationsFromMask(mask, config, 10.0, history);
  ASSERT_EQ(observations.size(), 1u);
  ASSERT_TRUE(observations[0].has_velocity);
  EXPECT_LT((observations[0].velocity_world - velocity).norm(), 1e-9);
  EXPECT_NEAR(observations[0].motion_speed_mps, velocity.norm(), 1e-9);
  EXPECT_EQ(observations[0].motion_sigma_mps, 0.0);  // no noise model given
  // With the depth noise model and the camera 2 m from the centroid: sigma_d = 1.4e-3 * 2^2 +
  // 1e-3 m; 9 points over 0.2 s; 1.2533 sqrt(2) sigma_d sqrt(9 / 0.2^2) / 9.
  DepthNoiseConfig noise;
  noise.sigma_d_quadratic = 1.4e-3;
  noise.sigma_d_constant_m = 1e-3;
  const std::vector<ObjectObservation> with_noise =
      ObservationsFromMask(mask, config, 10.0, history, &noise, Eigen::Vector3d(1.0, 2.0, 0.0));
  ASSERT_EQ(with_noise.size(), 1u);
  EXPECT_NEAR(with_noise[0].motion_sigma_mps,
              1.2533 * std::sqrt(2.0) * 6.6e-3 * std::sqrt(9 / 0.04) / 9, 1e-9);
}

TEST(ObservationsFromMask, RegionsWithFewPointsNearAPredictedTrackAreWeakObservations) {
  ObjectsConfig config;
  DynamicMask mask;
  DynamicRegion region;
  region.points.assign(config.track_min_points, 0);
  region.points_world.assign(config.track_min_points, Eigen::Vector3d::Zero());
  region.cells = 100;
  region.centroid_world = Eigen::Vector3d(1.0, 0.0, 2.0);
  mask.regions = {region};
  EXPECT_TRUE(ObservationsFromMask(mask, config, 0.0, {}).empty());
  const Eigen::Vector3d far(1.0, 0.0, 2.0 + config.gate_m + 0.1);
  EXPECT_TRUE(
      ObservationsFromMask(mask, config, 0.0, {}, nullptr, Eigen::Vector3d::Zero(), {far}).empty());
  const std::vector<ObjectObservation> near = ObservationsFromMask(
      mask, config, 0.0, {}, nullptr, Eigen::Vector3d::Zero(), {Eigen::Vector3d(1.2, 0, 2)});
  ASSERT_EQ(near.size(), 1u);
  EXPECT_TRUE(near[0].weak);
}

TEST(ObjectTracker, WeakObservationsStartNoTrackAndKeepNoneAliveBeyondMaxUnseen) {
  ObjectsConfig config;
  ObjectTracker tracker{config};
  const Eigen::Vector3d grey(0.5, 0.5, 0.5), v(1.0, 0.0, 0.0);
  ObjectObservation weak = Observe({0.0, 0.0, 2.0}, grey, v);
  weak.weak = true;
  tracker.Update(0.0, {weak});
  EXPECT_EQ(tracker.track_count(), 0);
  Eigen::Vector3d p(0.0, 0.0, 2.0);
  int i = 0;
  for (; i < 10; ++i, p += v / kFps) tracker.Update(i / kFps, {Observe(p, grey, v)});
  const double last_full = (i - 1) / kFps;
  // Weak observations keep it reported for up to max_unseen_s after its last full one.
  for (; i / kFps - last_full <= config.max_unseen_s - 0.01; ++i, p += v / kFps) {
    ObjectObservation o = Observe(p, grey, v);
    o.weak = true;
    EXPECT_EQ(tracker.Update(i / kFps, {o}).size(), 1u) << i;
  }
  for (int k = 0; k < 5; ++k, ++i, p += v / kFps) {
    ObjectObservation o = Observe(p, grey, v);
    o.weak = true;
    tracker.Update(i / kFps, {o});
  }
  EXPECT_EQ(tracker.track_count(), 0);
}

TEST(ObservationsFromMask, SmallRegionsAreLeftOut) {
  DynamicMask mask;
  DynamicRegion big, few_points, few_cells;
  big.points.assign(10, 0);
  big.points_world.assign(10, Eigen::Vector3d::Zero());  // a world position per point (same order)
  big.cells = 100;
  big.min_world = Eigen::Vector3d(0, 0, 0);
  big.max_world = Eigen::Vector3d(0.4, 1.8, 0.3);
  few_points = big;
  few_points.points.assign(2, 0);
  few_points.points_world.assign(2, Eigen::Vector3d::Zero());
  few_cells = big;
  few_cells.cells = 3;
  mask.regions = {big, few_points, few_cells};
  const std::vector<ObjectObservation> observations =
      ObservationsFromMask(mask, ObjectsConfig(), 0.0, {});
  ASSERT_EQ(observations.size(), 1u);
  EXPECT_EQ(observations[0].extent, Eigen::Vector3d(0.4, 1.8, 0.3));
  EXPECT_EQ(observations[0].points, 10);
}

}  // namespace
}  // namespace dslam
