#pragma once
// Moving things of the synthetic sequences: person-like walkers (articulated stacks of boxes),
// rigid boxes sliding back and forth, and a hanging sheet deforming with travelling waves. Each
// appends its geometry at time t to a SceneGeometry with its mask id. World frame: z up, floor z=0.

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "dslam/synth/geometry.h"

namespace dslam {
namespace synth {

/// A walker following a closed loop of floor waypoints at constant speed, pausing at waypoints.
struct WalkerParams {
  std::vector<Eigen::Vector2d> path_m;  ///< [m] closed loop of (x, y) floor points (world), >= 2
  std::vector<double> dwell_s;          ///< [s] pause at each waypoint (empty = none)
  double speed_mps = 1.0;               ///< [m/s] walking speed
  double start_offset_m = 0.0;          ///< [m] distance along the loop at t = 0
  double height_m = 1.75;               ///< [m] body height (all parts scale with it)
  double stride_m = 1.4;                ///< [m] distance walked per gait cycle (two steps)
  double hip_swing_deg = 25.0;          ///< [deg] thigh swing amplitude
  double knee_bend_deg = 40.0;          ///< [deg] maximum knee bend
  double arm_swing_deg = 22.0;          ///< [deg] arm swing amplitude (opposite to the legs)
  double idle_sway_deg = 12.0;          ///< [deg] torso yaw / arm gesture amplitude while pausing
  uint32_t look_seed = 1;               ///< seeds clothes colours and textures
};

/// Where a walker is at time t.
struct WalkerState {
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  ///< [m] floor point (world)
  double heading_rad = 0.0;                              ///< [rad] walking direction from +x
  double gait_phase_rad = 0.0;                           ///< [rad] 2 pi per stride
  double idle_time_s = -1.0;  ///< [s] time since the pause began, < 0 while walking
};

/// State of `walker` at `t_s` [s].
WalkerState WalkerStateAt(const WalkerParams& walker, double t_s);

/// [m/s] Velocity of the walker's floor point (world, z = 0) at `t_s` [s]: the walking speed along
/// the heading of the current path segment while walking, zero while pausing at a waypoint.
Eigen::Vector3d WalkerVelocityAt(const WalkerParams& walker, double t_s);

/// Appends the walker's 10 boxes (torso, head, upper/lower arms, thighs, shins) at `t_s`.
void AppendWalker(const WalkerParams& walker, double t_s, uint16_t object_id, SceneGeometry* scene);

/// A rigid box moving back and forth between two points at constant speed while turning.
struct MovingBoxParams {
  Eigen::Vector3d size_m{0.5, 0.5, 0.5};  ///< [m] full extents
  Eigen::Vector3d start_m{0, 0, 0.25};    ///< [m] centre at t = 0 (world)
  Eigen::Vector3d end_m{1, 0, 0.25};      ///< [m] turning point of the motion (world)
  double speed_mps = 0.09;                ///< [m/s] (0.09 m/s = 3 mm per frame at 30 Hz)
  double yaw_rate_dps = 0.0;              ///< [deg/s] rotation about the vertical axis
  uint32_t look_seed = 1;
};

/// [m] Centre of the moving box (world) at `t_s` [s].
Eigen::Vector3d MovingBoxCentreAt(const MovingBoxParams& box, double t_s);

/// [m/s] Velocity of the moving box's centre (world) at `t_s` [s]: speed_mps towards end_m on the
/// way out, towards start_m on the way back; zero when start_m == end_m.
Eigen::Vector3d MovingBoxVelocityAt(const MovingBoxParams& box, double t_s);

/// Appends the moving box at `t_s`.
void AppendMovingBox(const MovingBoxParams& box, double t_s, uint16_t object_id,
                     SceneGeometry* scene);

/// A sheet hanging from its top edge, deformed out of plane by travelling waves that grow
/// linearly from the (fixed) top edge to the bottom edge.
struct SheetParams {
  Eigen::Vector3d top_left_m{-1.0, 1.0, 2.2};  ///< [m] top-left corner (world)
  double yaw_deg = 0.0;       ///< [deg] sheet spans +x rotated by this about z; faces -y
  double width_m = 1.6;       ///< [m]
  double height_m = 1.6;      ///< [m]
  int columns = 32;           ///< grid quads across
  int rows = 24;              ///< grid quads down
  double amplitude_m = 0.15;  ///< [m] out-of-plane amplitude at the bottom edge
  double wavelength_m = 0.9;  ///< [m] horizontal wavelength
  double frequency_hz = 0.6;  ///< [Hz] wave frequency
  uint32_t look_seed = 1;
};

/// Appends the sheet's triangles at `t_s`.
void AppendSheet(const SheetParams& sheet, double t_s, uint16_t object_id, SceneGeometry* scene);

/// Out-of-plane displacement [m] of the sheet at surface point (s across, h down) [m] at t_s.
double SheetDisplacement(const SheetParams& sheet, double s_m, double h_m, double t_s);

}  // namespace synth
}  // namespace dslam
