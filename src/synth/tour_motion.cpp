#include "dslam/synth/tour_motion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "dslam/synth/camera_motion.h"
#include "dslam/synth/texture.h"

namespace dslam {
namespace synth {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;
constexpr double kDegToRad = M_PI / 180.0;
constexpr int kArcSamples = 1440;  ///< samples of the ellipse for its arc length

Eigen::Vector2d EllipsePoint(const TourParams& p, double theta) {
  return p.centre_m +
         Eigen::Vector2d(p.semi_axes_m.x() * std::cos(theta), p.semi_axes_m.y() * std::sin(theta));
}

/// Cumulative arc length [m] at kArcSamples + 1 equally spaced theta from the start angle over one
/// lap (chords; their error is below 1e-5 of the length for the default ellipse).
std::vector<double> ArcLengths(const TourParams& p) {
  std::vector<double> s(kArcSamples + 1, 0.0);
  const double theta0 = p.start_angle_deg * kDegToRad;
  Eigen::Vector2d previous = EllipsePoint(p, theta0);
  for (int i = 1; i <= kArcSamples; ++i) {
    const Eigen::Vector2d q = EllipsePoint(p, theta0 + kTwoPi * i / kArcSamples);
    s[i] = s[i - 1] + (q - previous).norm();
    previous = q;
  }
  return s;
}

/// theta [rad] of the point `distance_m` along the ellipse from the start (any distance >= 0).
double ThetaAtDistance(const TourParams& p, double distance_m) {
  const std::vector<double> s = ArcLengths(p);
  const double lap = s.back();
  const double laps = std::floor(distance_m / lap);
  const double d = distance_m - laps * lap;
  const int i = static_cast<int>(std::upper_bound(s.begin(), s.end(), d) - s.begin()) - 1;
  const int k = std::clamp(i, 0, kArcSamples - 1);
  const double fraction = (d - s[k]) / std::max(1e-12, s[k + 1] - s[k]);
  return p.start_angle_deg * kDegToRad + kTwoPi * (laps + (k + fraction) / kArcSamples);
}

/// Phases [rad] of bob, sway, roll, pitch and yaw wander from the seed.
std::array<double, 5> Phases(uint32_t seed) {
  std::array<double, 5> phase;
  for (int i = 0; i < 5; ++i) phase[i] = kTwoPi * HashToUnit(Hash3(seed, i, 7));
  return phase;
}

}  // namespace

double TourLapLength(const TourParams& params) { return ArcLengths(params).back(); }

double TourLapTime(const TourParams& params) { return TourLapLength(params) / params.speed_mps; }

Eigen::Isometry3d TourPoseAt(const TourParams& p, double t_s, uint32_t seed) {
  const double theta = ThetaAtDistance(p, p.speed_mps * t_s);
  const Eigen::Vector2d ahead =
      Eigen::Vector2d(-p.semi_axes_m.x() * std::sin(theta), p.semi_axes_m.y() * std::cos(theta))
          .normalized();
  const Eigen::Vector2d outward(ahead.y(), -ahead.x());  // right of a counter-clockwise walk
  const std::array<double, 5> phase = Phases(seed);
  const double step = kTwoPi * p.step_frequency_hz * t_s;
  auto wave = [](double amplitude, double angle) { return amplitude * std::sin(angle); };

  Eigen::Vector3d position(0.0, 0.0, p.height_m + wave(p.bob_m, step + phase[0]));
  position.head<2>() = EllipsePoint(p, theta) + wave(p.sway_m, 0.5 * step + phase[1]) * outward;
  const double look = p.look_outward_deg * kDegToRad;
  const Eigen::Vector2d view = std::cos(look) * ahead + std::sin(look) * outward;
  const double pitch = p.pitch_down_deg * kDegToRad;
  const Eigen::Vector3d forward(std::cos(pitch) * view.x(), std::cos(pitch) * view.y(),
                                -std::sin(pitch));
  const double yaw =
      wave(p.yaw_wander_deg * kDegToRad, kTwoPi * t_s / p.yaw_wander_period_s + phase[4]);
  const double roll = wave(p.wobble_deg * kDegToRad, 0.5 * step + phase[2]);
  const double nod = wave(p.wobble_deg * kDegToRad, step + phase[3]);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = position;
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                  LookAtRotation(position, position + forward) *
                  Eigen::AngleAxisd(nod, Eigen::Vector3d::UnitX()).toRotationMatrix() *
                  Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

}  // namespace synth
}  // namespace dslam
