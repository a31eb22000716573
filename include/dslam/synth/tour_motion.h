#pragma once
// The `tour` camera motion of dslam_synth: a hand-held camera carried at walking pace round a
// closed ellipse on the floor, looking outwards and ahead, so that after one lap it sees its first
// views again (the `room_tour` scenario, a test of loop closing). World frame as in
// camera_motion.h: x right, y into the room, z up; poses are T_world_camera of the optical frame.

#include <cstdint>

#include <Eigen/Geometry>

namespace dslam {
namespace synth {

/// Parameters of the tour. The camera centre moves at constant speed along the ellipse
/// centre_m + (semi_axes_m.x cos(theta), semi_axes_m.y sin(theta)), counter-clockwise seen from
/// above, plus the hand-held bob and sway below.
struct TourParams {
  Eigen::Vector2d centre_m{0.0, -0.1};    ///< [m] centre of the ellipse (world x, y)
  Eigen::Vector2d semi_axes_m{1.5, 1.1};  ///< [m] semi-axes along world x and y
  double height_m = 1.35;                 ///< [m] mean camera height above the floor
  double speed_mps = 0.45;                ///< [m/s] walking speed along the ellipse
  double start_angle_deg = -90.0;         ///< [deg] theta at t = 0 (-90: the side nearest y min)
  /// [deg] heading of the view from the walking direction towards the outside of the ellipse
  /// (0: straight ahead, 90: straight outwards).
  double look_outward_deg = 55.0;
  double pitch_down_deg = 10.0;    ///< [deg] the view's tilt below the horizon
  double step_frequency_hz = 1.8;  ///< [Hz] steps per second (bob and pitch wobble)
  double bob_m = 0.012;            ///< [m] vertical bob amplitude, at the step frequency
  double sway_m = 0.015;           ///< [m] sideways sway amplitude, at half the step frequency
  double wobble_deg = 1.0;         ///< [deg] roll (half step frequency) and pitch (step) amplitude
  double yaw_wander_deg = 3.0;     ///< [deg] slow yaw wander of the hand about the vertical
  double yaw_wander_period_s = 7.0;  ///< [s] period of the yaw wander
};

/// [m] Length of one lap of the ellipse (numerically integrated).
double TourLapLength(const TourParams& params);

/// [s] Time of one lap at params.speed_mps.
double TourLapTime(const TourParams& params);

/// T_world_camera at `t_s` [s] after the start; `seed` sets the phases of bob, sway, wobble and
/// wander (bounded: after each lap the camera is back within a few centimetres and degrees).
Eigen::Isometry3d TourPoseAt(const TourParams& params, double t_s, uint32_t seed);

}  // namespace synth
}  // namespace dslam
