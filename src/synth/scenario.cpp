// The named scenarios of dslam_synth (scenario.h). Every number here is listed in
// docs/readme/synth.md; change both together.
#include "dslam/synth/scenario.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dslam {
namespace synth {
namespace {

WalkerParams Walker(std::vector<Eigen::Vector2d> path, double start_offset_m, uint32_t look) {
  WalkerParams w;
  w.path_m = std::move(path);
  w.start_offset_m = start_offset_m;
  w.look_seed = look;
  return w;
}

/// Two walkers on loops 1-2.5 m in front of the base camera, crossing its view (walking*).
std::vector<WalkerParams> TwoWalkers(uint32_t seed) {
  WalkerParams a = Walker({{-0.7, -0.2}, {0.7, -0.2}, {0.3, -0.75}}, 0.0, seed * 2 + 1);
  a.dwell_s = {0.0, 0.0, 1.5};
  WalkerParams b = Walker({{0.9, 0.4}, {-0.9, 0.4}, {-0.3, -0.6}}, 1.0, seed * 2 + 2);
  b.dwell_s = {0.0, 0.0, 1.0};
  return {a, b};
}

Scenario Base(const std::string& name, uint32_t seed, CameraMotionKind motion) {
  Scenario s;
  s.name = name;
  s.seed = seed;
  s.camera.kind = motion;
  return s;
}

/// Static room, camera turning fast about all three axes in place with a 15 ms exposure (modelled
/// on TUM fr1/rpy). Over 720 frames the peak rates about the camera's own axes are 55.1 (x),
/// 52.9 (y) and 53.0 (z) deg/s (test/synth/fast_rotation_test.cpp); the hand-shake translation
/// stays within 4.1 cm (the norm of its amplitudes) of the base position.
Scenario FastRotation(const std::string& name, uint32_t seed) {
  Scenario s = Base(name, seed, CameraMotionKind::kRpy);
  s.frames = 720;
  s.camera.rpy_amplitude_deg = {18.0, 15.0, 20.0};  // roll, pitch, yaw
  s.camera.rpy_period_s = {2.6, 2.2, 3.0};
  s.camera.rpy_translation_m = {0.025, 0.02, 0.025};
  s.camera.rpy_translation_period_s = {2.9, 2.4, 3.4};
  s.camera.exposure.exposure_s = 0.015;
  return s;
}

/// A walker that walks `laps` times round its loop in `period_s` [s], pausing `dwell_s` per lap:
/// its speed is set so that a lap takes period_s / laps, and its stride (near the default 1.4 m)
/// so that the period's walking distance is a whole number of strides; position, heading, gait
/// and idle gestures then repeat with period_s.
WalkerParams PeriodicWalker(std::vector<Eigen::Vector2d> path, std::vector<double> dwell_s,
                            int laps, double period_s, double start_offset_m, uint32_t look) {
  WalkerParams w = Walker(std::move(path), start_offset_m, look);
  w.dwell_s = std::move(dwell_s);
  double loop_length_m = 0.0, pause_s = 0.0;
  for (size_t i = 0; i < w.path_m.size(); ++i) {
    loop_length_m += (w.path_m[(i + 1) % w.path_m.size()] - w.path_m[i]).norm();
  }
  for (double d : w.dwell_s) pause_s += d;
  w.speed_mps = loop_length_m / (period_s / laps - pause_s);
  const double distance_m = laps * loop_length_m;
  w.stride_m = distance_m / std::max(1.0, std::round(distance_m / w.stride_m));
  return w;
}

/// Static room, camera on a closed half-sphere path (azimuth period 20 s, elevation period 10 s)
/// and three walkers whose loops all repeat after 20 s: frame 600 (at 30 Hz) shows the geometry of
/// frame 0, so the 600 frames replay in a loop without a jump (test/synth/loop_test.cpp).
Scenario Loop(const std::string& name, uint32_t seed) {
  Scenario s = Base(name, seed, CameraMotionKind::kHalfsphere);
  s.period_s = 20.0;
  s.frames = static_cast<int>(std::lround(s.period_s * s.fps));
  s.camera.halfsphere_azimuth_period_s = s.period_s;
  s.camera.halfsphere_elevation_period_s = s.period_s / 2.0;
  // The loops of `walking` (4 and 3 laps per period) and one across the room in front of the
  // table (2 laps: there and back, pausing 1 s at each end).
  s.walkers = {
      PeriodicWalker({{-0.7, -0.2}, {0.7, -0.2}, {0.3, -0.75}}, {0.0, 0.0, 1.5}, 4, s.period_s, 0.0,
                     seed * 2 + 1),
      PeriodicWalker({{0.9, 0.4}, {-0.9, 0.4}, {-0.3, -0.6}}, {0.0, 0.0, 1.0}, 3, s.period_s, 1.0,
                     seed * 2 + 2),
      PeriodicWalker({{-1.8, 1.0}, {1.8, 1.0}}, {1.0, 1.0}, 2, s.period_s, 0.0, seed * 2 + 3)};
  return s;
}

/// Static room, the camera carried once round the room (`tour`, tour_motion.h: looking outwards and
/// ahead) and on for 6 s into its first views again. Walker 1 stands at the front wall's left end
/// until 1.5 s before the lap ends, then crosses the first views once; walker 2 walks the same
/// stretch along the right wall back and forth, once per half lap, so it is in the same place
/// whenever the camera passes: seen there in both laps, by views that are alike.
Scenario RoomTour(const std::string& name, uint32_t seed) {
  Scenario s = Base(name, seed, CameraMotionKind::kTour);
  const double lap_s = TourLapTime(s.camera.tour);
  s.frames = static_cast<int>(std::lround((lap_s + 6.0) * s.fps));
  WalkerParams front = Walker({{-1.8, -2.4}, {2.7, -2.4}}, 0.0, seed * 2 + 1);
  front.speed_mps = 1.1;
  front.dwell_s = {lap_s - 1.5, 60.0};  // waits at the left end from t = 0, then walks once
  const double crossing_s = 4.5 / front.speed_mps;
  front.start_offset_m = (2.0 * crossing_s + front.dwell_s[1]) * front.speed_mps;
  const double side_pause_s = 1.0;
  WalkerParams side = Walker({{2.35, -2.0}, {2.35, 1.2}}, 0.0, seed * 2 + 2);
  side.dwell_s = {side_pause_s, side_pause_s};
  side.speed_mps = 2.0 * 3.2 / (0.5 * lap_s - 2.0 * side_pause_s);  // a back and forth per half lap
  s.walkers = {front, side};
  return s;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> ScenarioNames() {
  return {{"static_room", "textured room, nothing moves, camera xyz"},
          {"static_room_distorted",
           "static room, camera rpy, lens with TUM fr1's distortion (k1 0.26, k2 -0.95)"},
          {"static_room_kinect",
           "static room, camera xyz, a structured-light camera's depth errors (Kinect v1)"},
          {"walking", "two walkers covering much of the view, camera xyz"},
          {"walking_kinect", "'walking' with a structured-light camera's depth errors"},
          {"walking_static", "the two walkers of 'walking', static camera (mm jitter)"},
          {"walking_halfsphere", "the two walkers of 'walking', camera on a half sphere"},
          {"close_person", "one walker stopping 0.7 m in front of the camera, camera small xyz"},
          {"close_person_kinect", "'close_person' with a structured-light camera's depth errors"},
          {"slow_box", "two boxes sliding 3 and 1.5 mm per frame, camera xyz"},
          {"nonrigid_sheet", "a hanging sheet deformed by travelling waves, camera xyz"},
          {"fast_rotation", "static room, handheld fast roll/pitch/yaw with 15 ms motion blur"},
          {"fast_rotation_kinect",
           "'fast_rotation' with a structured-light camera's depth errors"},
          {"loop", "three walkers, camera on a half sphere; everything repeats after 20 s"},
          {"room_tour",
           "camera carried once round the room and into its first views again, two walkers"}};
}

Scenario MakeScenario(const std::string& name, uint32_t seed) {
  if (name == "static_room") return Base(name, seed, CameraMotionKind::kXyz);
  if (name == "static_room_distorted") {
    // Rotating, so that points cross the image and meet different parts of the lens.
    Scenario s = Base(name, seed, CameraMotionKind::kRpy);
    // The published calibration of TUM RGB-D's freiburg1 colour camera (plumb_bob).
    s.sensor.distortion = {0.2624, -0.9531, -0.0054, 0.0026, 1.1633};
    return s;
  }
  const std::string kKinect = "_kinect";
  if (name.size() > kKinect.size() &&
      name.compare(name.size() - kKinect.size(), kKinect.size(), kKinect) == 0) {
    // The scene named before the suffix, its depth as a structured-light camera delivers it.
    Scenario s = MakeScenario(name.substr(0, name.size() - kKinect.size()), seed);
    s.name = name;
    s.sensor.structured_light.enabled = true;
    return s;
  }
  if (name == "walking" || name == "walking_static" || name == "walking_halfsphere") {
    const CameraMotionKind motion = name == "walking"          ? CameraMotionKind::kXyz
                                    : name == "walking_static" ? CameraMotionKind::kStatic
                                                               : CameraMotionKind::kHalfsphere;
    Scenario s = Base(name, seed, motion);
    s.walkers = TwoWalkers(seed);
    return s;
  }
  if (name == "close_person") {
    Scenario s = Base(name, seed, CameraMotionKind::kXyz);
    s.camera.xyz_amplitude_m = {0.1, 0.05, 0.1};
    WalkerParams w = Walker({{1.8, 0.9}, {0.0, -1.1}, {-1.8, 0.9}}, 0.5, seed * 2 + 1);
    w.dwell_s = {0.0, 4.0, 0.0};
    s.walkers = {w};
    return s;
  }
  if (name == "slow_box") {
    Scenario s = Base(name, seed, CameraMotionKind::kXyz);
    MovingBoxParams a;
    a.size_m = {0.6, 0.6, 0.6};
    a.start_m = {-1.0, 0.3, 0.3};
    a.end_m = {1.0, 0.3, 0.3};
    a.speed_mps = 0.09;  // 3 mm per frame
    a.look_seed = seed * 2 + 1;
    MovingBoxParams b;
    b.size_m = {0.4, 0.4, 0.4};
    b.start_m = {0.8, 1.0, 0.2};
    b.end_m = {-0.4, 1.0, 0.2};
    b.speed_mps = 0.045;  // 1.5 mm per frame
    b.yaw_rate_dps = 3.0;
    b.look_seed = seed * 2 + 2;
    s.boxes = {a, b};
    return s;
  }
  if (name == "nonrigid_sheet") {
    Scenario s = Base(name, seed, CameraMotionKind::kXyz);
    SheetParams sheet;
    sheet.top_left_m = {-0.7, 0.8, 2.0};
    sheet.width_m = 1.4;
    sheet.height_m = 1.4;
    sheet.look_seed = seed;
    s.sheets = {sheet};
    return s;
  }
  if (name == "fast_rotation") return FastRotation(name, seed);
  if (name == "loop") return Loop(name, seed);
  if (name == "room_tour") return RoomTour(name, seed);
  throw std::invalid_argument("unknown scenario '" + name + "'");
}

void UseSensorDepthNoise(const SensorParams& sensor, DepthNoiseConfig* depth_noise) {
  if (sensor.structured_light.enabled) return;
  depth_noise->sigma_d_quadratic = sensor.depth_sigma_quadratic_per_m;
  depth_noise->sigma_d_constant_m = sensor.depth_sigma_constant_m;
}

}  // namespace synth
}  // namespace dslam
