#pragma once
// Camera trajectories of the synthetic sequences, named after the TUM RGB-D motions. World frame:
// x right, y into the room, z up, floor at z = 0. Poses are T_world_camera of the optical frame
// (x right, y down, z forward).

#include <string>

#include <Eigen/Geometry>

#include "dslam/synth/tour_motion.h"

namespace dslam {
namespace synth {

/// The four TUM-like camera motions, and a walk round the room (tour_motion.h).
enum class CameraMotionKind { kStatic, kXyz, kRpy, kHalfsphere, kTour };

/// Parses "static", "xyz", "rpy", "halfsphere" or "tour"; throws std::invalid_argument otherwise.
CameraMotionKind ParseCameraMotion(const std::string& name);

/// The name ParseCameraMotion() accepts for `kind`.
std::string CameraMotionName(CameraMotionKind kind);

/// Exposure of the colour camera. With exposure_s > 0 the colour image of a frame is the average
/// of sub-frame renders spread over [t - exposure_s / 2, t + exposure_s / 2] around the frame's
/// time t (motion blur, motion_blur.h); depth, mask and ground truth stay those of time t.
struct ExposureParams {
  double exposure_s = 0.0;   ///< [s] shutter open time; 0 = sharp (one render at t)
  double max_step_px = 1.5;  ///< [px] largest image motion allowed between two sub-frames
  int max_subframes = 15;    ///< cap on the sub-frames per frame (render time); even = one less
};

/// Parameters of the camera motion; every motion is a sum of sinusoids starting at the base pose.
struct CameraMotionParams {
  CameraMotionKind kind = CameraMotionKind::kXyz;
  Eigen::Vector3d position_m{0.0, -1.8, 1.3};  ///< [m] base camera centre (world)
  Eigen::Vector3d look_at_m{0.0, 1.5, 0.9};    ///< [m] point the base pose looks at (world)
  double jitter_translation_m = 0.002;         ///< [m] static: amplitude per axis
  double jitter_rotation_deg = 0.15;           ///< [deg] static: amplitude per axis
  double jitter_period_s = 1.3;  ///< [s] static: base period (axes use 1x, 1.37x, 1.71x)
  /// [m] xyz: amplitudes along the base camera's x (right), y (down), z (forward) axes.
  Eigen::Vector3d xyz_amplitude_m{0.25, 0.1, 0.2};
  Eigen::Vector3d xyz_period_s{6.0, 4.5, 8.0};  ///< [s] xyz: periods per axis
  /// [deg] rpy: amplitudes of rotations about the camera's z (roll), x (pitch), y (yaw) axes.
  Eigen::Vector3d rpy_amplitude_deg{12.0, 10.0, 18.0};
  Eigen::Vector3d rpy_period_s{7.0, 5.0, 9.0};  ///< [s] rpy: periods (roll, pitch, yaw)
  double halfsphere_radius_m = 0.6;             ///< [m] radius of the half sphere
  double halfsphere_azimuth_deg = 60.0;         ///< [deg] azimuth amplitude (sinusoid)
  double halfsphere_elevation_deg = 40.0;       ///< [deg] elevation range [0, this] (raised cosine)
  double halfsphere_azimuth_period_s = 10.0;    ///< [s]
  double halfsphere_elevation_period_s = 7.0;   ///< [s]
  /// [m] rpy: hand-shake translation amplitudes along the base camera's x, y, z axes (0 = none).
  Eigen::Vector3d rpy_translation_m{0.0, 0.0, 0.0};
  /// [s] rpy: periods of the hand-shake translation (x, y, z).
  Eigen::Vector3d rpy_translation_period_s{2.9, 2.4, 3.4};
  /// tour: the walk round the room (tour_motion.h); the base pose is not used.
  TourParams tour;
  /// Colour exposure (motion blur, motion_blur.h); exposure_s = 0 (the default) = sharp.
  ExposureParams exposure;
};

/// Rotation of an optical frame at `position` looking at `target` with world z up (no roll).
Eigen::Matrix3d LookAtRotation(const Eigen::Vector3d& position, const Eigen::Vector3d& target);

/// T_world_camera at time `t_s` [s] after the start of the sequence; `seed` sets the phases of the
/// static jitter and of the tour's hand-held motion only.
Eigen::Isometry3d CameraPoseAt(const CameraMotionParams& params, double t_s, uint32_t seed);

}  // namespace synth
}  // namespace dslam
