#include "dslam/mapping/object_tracker.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace dslam {
namespace {

/// [m/s] prior standard deviation of a new track's velocity (a brisk walk).
constexpr double kInitialVelocitySigmaMps = 1.5;

}  // namespace

std::vector<ObjectObservation> ObservationsFromMask(const DynamicMask& mask,
                                                    const ObjectsConfig& config) {
  std::vector<ObjectObservation> observations;
  for (const DynamicRegion& region : mask.regions) {
    if (static_cast<int>(region.points.size()) < config.min_points) continue;
    if (region.cells < config.min_cells) continue;
    ObjectObservation observation;
    observation.centroid_world = region.centroid_world;
    observation.extent = region.max_world - region.min_world;
    observation.colour = region.mean_colour;
    observation.points = static_cast<int>(region.points.size());
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

void ObjectTracker::Correct(Track* track, const ObjectObservation& observation,
                            double stamp_s) const {
  // Position measurement z = H x + n, H = [I 0], n ~ N(0, sigma^2 I).
  const double r = config_.position_sigma_m * config_.position_sigma_m;
  const Eigen::Matrix3d S = track->P.topLeftCorner<3, 3>() + r * Eigen::Matrix3d::Identity();
  const Eigen::Matrix<double, 6, 3> K = track->P.leftCols<3>() * S.inverse();
  track->x += K * (observation.centroid_world - track->x.head<3>());
  Eigen::Matrix<double, 6, 6> I_KH = Eigen::Matrix<double, 6, 6>::Identity();
  I_KH.leftCols<3>() -= K;
  track->P = I_KH * track->P;
  track->P = 0.5 * (track->P + track->P.transpose()).eval();
  track->last = observation;
  track->last_seen_s = stamp_s;
  ++track->hits;
}

ObjectTracker::Track ObjectTracker::StartTrack(const ObjectObservation& observation,
                                               double stamp_s) {
  Track track;
  track.id = next_id_++;
  track.x.head<3>() = observation.centroid_world;
  track.P.setZero();
  track.P.topLeftCorner<3, 3>().diagonal().setConstant(config_.position_sigma_m *
                                                       config_.position_sigma_m);
  track.P.bottomRightCorner<3, 3>().diagonal().setConstant(kInitialVelocitySigmaMps *
                                                           kInitialVelocitySigmaMps);
  track.last = observation;
  track.first_seen_s = track.last_seen_s = stamp_s;
  track.hits = 1;
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
    } else {
      tracks_.push_back(StartTrack(observations[o], stamp_s));
    }
  }
  tracks_.erase(std::remove_if(
                    tracks_.begin(), tracks_.end(),
                    [&](const Track& t) { return stamp_s - t.last_seen_s > config_.max_unseen_s; }),
                tracks_.end());
  std::vector<TrackedObject> reported;
  for (const Track& track : tracks_) {
    if (track.last_seen_s != stamp_s || track.hits < config_.min_hits) continue;
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
