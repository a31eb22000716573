#include "dslam/mapping/object_tracker.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "dslam/core/depth_uncertainty.h"

namespace dslam {
namespace {

/// [m/s] prior standard deviation of a new track's velocity (a brisk walk).
constexpr double kInitialVelocitySigmaMps = 1.5;
/// Points an observed velocity needs.
constexpr int kMinVelocityPoints = 3;
/// Mask cells a region needs to become an observation.
constexpr int kMinCells = 20;

double MedianOf(std::vector<double> values) {
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  if (values.size() % 2 == 1) return values[mid];
  return 0.5 * (values[mid] + *std::max_element(values.begin(), values.begin() + mid));
}

/// Per-axis median velocity [m/s] of the region's points, each from its oldest position in
/// `history` within `baseline_s` [s]; false when fewer than `min_points` points have one.
/// `noise_rate` [1/s], when given, receives sqrt(sum of 1 / dt^2) / n over the n points and their
/// baselines dt: a position sigma times it is the sigma of the points' mean velocity.
bool RegionVelocity(const DynamicRegion& region, const std::deque<PointPositions>& history,
                    double stamp_s, double baseline_s, const ObjectsConfig& config,
                    Eigen::Vector3d* velocity, double* noise_rate = nullptr) {
  std::vector<double> axes[3];
  double rate2_sum = 0.0;
  for (size_t i = 0; i < region.points.size(); ++i) {
    Eigen::Vector3d v;
    double dt_s = 0.0;
    if (PointVelocity(region.points[i], region.points_world[i], history, stamp_s, baseline_s,
                      config, &v, &dt_s)) {
      for (int a = 0; a < 3; ++a) axes[a].push_back(v[a]);
      rate2_sum += 1.0 / (dt_s * dt_s);
    }
  }
  if (static_cast<int>(axes[0].size()) < kMinVelocityPoints) return false;
  if (noise_rate != nullptr) *noise_rate = std::sqrt(rate2_sum) / axes[0].size();
  for (int a = 0; a < 3; ++a) (*velocity)[a] = MedianOf(axes[a]);
  return true;
}

}  // namespace

bool PointVelocity(PointId id, const Eigen::Vector3d& p_world,
                   const std::deque<PointPositions>& history, double stamp_s, double baseline_s,
                   const ObjectsConfig& config, Eigen::Vector3d* velocity, double* dt_out) {
  for (const PointPositions& before : history) {
    const double dt_s = stamp_s - before.stamp_s;
    if (dt_s > baseline_s || dt_s <= 0.0) continue;
    const auto p = before.by_id.find(id);
    if (p == before.by_id.end()) continue;
    *velocity = (p_world - p->second) / dt_s;
    if (dt_out != nullptr) *dt_out = dt_s;
    // Faster: the point was matched to another thing's feature (an unmarked point follows its
    // matches), not a motion.
    return velocity->norm() <= config.max_point_speed_mps;
  }
  return false;
}

PointPositions PositionsOf(const DynamicMask& mask, double stamp_s) {
  PointPositions positions;
  positions.stamp_s = stamp_s;
  for (const DynamicRegion& region : mask.regions) {
    for (size_t i = 0; i < region.points.size(); ++i) {
      positions.by_id[region.points[i]] = region.points_world[i];
    }
  }
  return positions;
}

std::vector<ObjectObservation> ObservationsFromMask(
    const DynamicMask& mask, const ObjectsConfig& config, double stamp_s,
    const std::deque<PointPositions>& history, const DepthNoiseConfig* noise,
    const Eigen::Vector3d& camera_world, const std::vector<Eigen::Vector3d>& near_world) {
  std::vector<ObjectObservation> observations;
  for (const DynamicRegion& region : mask.regions) {
    const int n = static_cast<int>(region.points.size());
    const bool near = std::any_of(near_world.begin(), near_world.end(), [&](const auto& p) {
      return (p - region.centroid_world).norm() <= config.gate_m;
    });
    if (n < config.min_points && !(near && n >= config.track_min_points)) continue;
    if (region.cells < kMinCells) continue;
    ObjectObservation observation;
    observation.weak = n < config.min_points;
    observation.centroid_world = region.centroid_world;
    observation.extent = region.max_world - region.min_world;
    observation.colour = region.mean_colour;
    observation.points = static_cast<int>(region.points.size());
    observation.has_velocity = RegionVelocity(region, history, stamp_s, config.velocity_baseline_s,
                                              config, &observation.velocity_world);
    Eigen::Vector3d motion;
    double noise_rate = 0.0;
    if (RegionVelocity(region, history, stamp_s, config.motion_baseline_s, config, &motion,
                       &noise_rate)) {
      observation.motion_speed_mps = motion.norm();
      if (noise != nullptr) {
        // A point's velocity differs two depth measurements over its baseline (sqrt(2) sigma_d
        // / dt); a median has about 1.2533 times the sigma of the mean.
        const double sigma_d = DepthSigma((region.centroid_world - camera_world).norm(), *noise);
        observation.motion_sigma_mps = 1.2533 * std::sqrt(2.0) * sigma_d * noise_rate;
      }
    }
    observations.push_back(observation);
  }
  return observations;
}

void ObjectTracker::Predict(Track* track, double dt_s) const {
  Eigen::Matrix<double, 6, 6> F = Eigen::Matrix<double, 6, 6>::Identity();
  F.topRightCorner<3, 3>().diagonal().setConstant(dt_s);
  // White acceleration noise: Q = q [dt^4/4, dt^3/2; dt^3/2, dt^2] per axis.
  const double q = config_.acceleration_sigma_mps2 * config_.acceleration_sigma_mps2;
  Eigen::Matrix<double, 6, 6> Q = Eigen::Matrix<double, 6, 6>::Zero();
  Q.topLeftCorner<3, 3>().diagonal().setConstant(q * std::pow(dt_s, 4) / 4.0);
  Q.topRightCorner<3, 3>().diagonal().setConstant(q * std::pow(dt_s, 3) / 2.0);
  Q.bottomLeftCorner<3, 3>().diagonal().setConstant(q * std::pow(dt_s, 3) / 2.0);
  Q.bottomRightCorner<3, 3>().diagonal().setConstant(q * dt_s * dt_s);
  track->x = F * track->x;
  track->P = F * track->P * F.transpose() + Q;
}

bool ObjectTracker::Moving(const ObjectObservation& observation) const {
  return observation.motion_speed_mps >= config_.min_speed_mps &&
         observation.motion_speed_mps >= config_.motion_sigma_factor * observation.motion_sigma_mps;
}

void ObjectTracker::ResetOnManeuver(Track* track, const ObjectObservation& observation) const {
  Eigen::Matrix3d S = track->P.bottomRightCorner<3, 3>();
  S.diagonal().array() += config_.velocity_sigma_mps * config_.velocity_sigma_mps;
  const Eigen::Vector3d y = observation.velocity_world - track->x.tail<3>();
  const double nis = y.dot(S.ldlt().solve(y));
  const bool maneuver = nis + track->last_velocity_nis > config_.maneuver_chi2;
  track->last_velocity_nis = maneuver ? 0.0 : nis;
  if (!maneuver) return;
  track->P.topRightCorner<3, 3>().setZero();
  track->P.bottomLeftCorner<3, 3>().setZero();
  track->P.bottomRightCorner<3, 3>() =
      Eigen::Matrix3d::Identity() * (kInitialVelocitySigmaMps * kInitialVelocitySigmaMps);
}

void ObjectTracker::Correct(Track* track, const ObjectObservation& observation,
                            double stamp_s) const {
  // z = H x + n: the centroid (H = [I 0]) and, when measured, the points' velocity (H = I).
  const int m = observation.has_velocity ? 6 : 3;
  if (observation.has_velocity && config_.maneuver_chi2 > 0.0) ResetOnManeuver(track, observation);
  Eigen::Matrix<double, 6, 1> z;
  z << observation.centroid_world, observation.velocity_world;
  Eigen::Matrix<double, 6, 1> r;
  r << Eigen::Vector3d::Constant(config_.position_sigma_m * config_.position_sigma_m),
      Eigen::Vector3d::Constant(config_.velocity_sigma_mps * config_.velocity_sigma_mps);
  const Eigen::MatrixXd P_xz = track->P.leftCols(m);
  Eigen::MatrixXd S = track->P.topLeftCorner(m, m);
  S.diagonal() += r.head(m);
  const Eigen::MatrixXd K = P_xz * S.inverse();
  track->x += K * (z.head(m) - track->x.head(m));
  Eigen::Matrix<double, 6, 6> I_KH = Eigen::Matrix<double, 6, 6>::Identity();
  I_KH.leftCols(m) -= K;
  track->P = I_KH * track->P;
  track->P = 0.5 * (track->P + track->P.transpose()).eval();
  track->last = observation;
  track->last_seen_s = stamp_s;
  if (!observation.weak) track->last_full_s = stamp_s;
  ++track->hits;
  track->moving_streak = Moving(observation) ? track->moving_streak + 1 : 0;
  if (track->moving_streak >= config_.min_hits) track->moved = true;
}

ObjectTracker::Track ObjectTracker::StartTrack(const ObjectObservation& observation,
                                               double stamp_s) {
  Track track;
  track.id = next_id_++;
  track.x.head<3>() = observation.centroid_world;
  if (observation.has_velocity) track.x.tail<3>() = observation.velocity_world;
  track.P.setZero();
  track.P.topLeftCorner<3, 3>().diagonal().setConstant(config_.position_sigma_m *
                                                       config_.position_sigma_m);
  const double velocity_sigma =
      observation.has_velocity ? config_.velocity_sigma_mps : kInitialVelocitySigmaMps;
  track.P.bottomRightCorner<3, 3>().diagonal().setConstant(velocity_sigma * velocity_sigma);
  track.last = observation;
  track.first_seen_s = track.last_seen_s = track.last_full_s = stamp_s;
  track.hits = 1;
  track.moving_streak = Moving(observation) ? 1 : 0;
  track.moved = track.moving_streak >= config_.min_hits;
  return track;
}

std::vector<int> ObjectTracker::Associate(
    const std::vector<ObjectObservation>& observations) const {
  std::vector<std::tuple<double, int, int>> pairs;  // (cost, observation, track)
  for (int o = 0; o < static_cast<int>(observations.size()); ++o) {
    for (int t = 0; t < static_cast<int>(tracks_.size()); ++t) {
      const double distance = (observations[o].centroid_world - tracks_[t].x.head<3>()).norm();
      const double colour =
          (observations[o].colour - tracks_[t].last.colour).norm() / std::sqrt(3.0);
      const double cost = distance + config_.colour_weight_m * colour;
      if (cost <= config_.gate_m) pairs.emplace_back(cost, o, t);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<int> track_of(observations.size(), -1);
  std::vector<char> taken(tracks_.size(), 0);
  for (const auto& [cost, o, t] : pairs) {
    if (track_of[o] != -1 || taken[t]) continue;
    track_of[o] = t;
    taken[t] = 1;
  }
  return track_of;
}

std::vector<Eigen::Vector3d> ObjectTracker::PredictedPositions(double stamp_s) const {
  std::vector<Eigen::Vector3d> predicted;
  if (!has_stamp_ || !(stamp_s > last_stamp_s_) || stamp_s - last_stamp_s_ > config_.max_unseen_s) {
    return predicted;
  }
  for (const Track& track : tracks_) {
    if (!track.moved || stamp_s - track.last_full_s > config_.max_unseen_s) continue;
    predicted.push_back(track.x.head<3>() + (stamp_s - last_stamp_s_) * track.x.tail<3>());
  }
  return predicted;
}

std::vector<TrackedObject> ObjectTracker::Update(
    double stamp_s, const std::vector<ObjectObservation>& observations) {
  if (has_stamp_ &&
      (!(stamp_s > last_stamp_s_) || stamp_s - last_stamp_s_ > config_.max_unseen_s)) {
    tracks_.clear();
  }
  const double dt_s = has_stamp_ && !tracks_.empty() ? stamp_s - last_stamp_s_ : 0.0;
  has_stamp_ = true;
  last_stamp_s_ = stamp_s;
  for (Track& track : tracks_) Predict(&track, dt_s);
  const std::vector<int> track_of = Associate(observations);
  for (size_t o = 0; o < observations.size(); ++o) {
    if (track_of[o] >= 0) {
      Correct(&tracks_[track_of[o]], observations[o], stamp_s);
    } else if (!observations[o].weak) {
      tracks_.push_back(StartTrack(observations[o], stamp_s));
    }
  }
  tracks_.erase(std::remove_if(
                    tracks_.begin(), tracks_.end(),
                    [&](const Track& t) { return stamp_s - t.last_full_s > config_.max_unseen_s; }),
                tracks_.end());
  std::vector<TrackedObject> reported;
  for (const Track& track : tracks_) {
    if (!track.moved || stamp_s - track.last_seen_s > config_.coast_s) continue;
    TrackedObject object;
    object.id = track.id;
    object.position_world = track.x.head<3>();
    object.velocity_world = track.x.tail<3>();
    object.extent = track.last.extent;
    object.points = track.last.points;
    object.age_s = stamp_s - track.first_seen_s;
    reported.push_back(object);
  }
  return reported;
}

}  // namespace dslam
