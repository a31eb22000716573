#pragma once
// Named scenarios of dslam_synth: the room, its furniture, the moving things, the camera motion and
// the sensor model, with every parameter in a struct with units. Changing a scenario used by a
// benchmark means re-running and re-reporting that benchmark (docs/readme/synth.md lists them).

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dslam/core/camera.h"
#include "dslam/core/features_config.h"
#include "dslam/synth/actors.h"
#include "dslam/synth/camera_motion.h"
#include "dslam/synth/geometry.h"

namespace dslam {
namespace synth {

/// The room: an inward box with furniture along its walls. World frame z up, floor at z = 0.
struct RoomParams {
  Eigen::Vector3d min_corner_m{-3.0, -2.8, 0.0};  ///< [m]
  Eigen::Vector3d max_corner_m{3.0, 3.0, 2.8};    ///< [m]
  double furniture_jitter_m = 0.15;  ///< [m] seed-dependent shift of each furniture piece
};

/// Depth of a structured-light camera (Kinect v1, the camera of TUM RGB-D and Bonn): it measures
/// the disparity fx b / d of a projected pattern, matched over windows of pixels, so its errors are
/// disparity errors (growing as d^2 in depth), smooth over the image, partly fixed to the sensor
/// and partly new in every frame, and rounded to a fraction of a pixel; at a depth edge the nearer
/// surface's depth spreads onto the farther one. With the defaults the disparity error has a
/// standard deviation of 0.15 px: a depth sigma of 0.0038 d^2 per measurement [m, d in m] at
/// fx 525 px and b 0.075 m, and 0.0054 d^2 between two measurements, as the depth residuals of
/// real Kinect frames show (0.0046-0.0065 d^2 on Bonn crowd; docs/benchmarks/tracking.md, "Issue
/// 46, part 1"). Replaces SensorParams' Gaussian depth noise when enabled.
struct StructuredLightParams {
  bool enabled = false;
  double baseline_m = 0.075;         ///< [m] projector to depth camera
  double fixed_sigma_px = 0.10;      ///< [px] disparity error field fixed to the sensor (seed)
  double frame_sigma_px = 0.10;      ///< [px] disparity error field drawn anew for each frame
  double pixel_sigma_px = 0.03;      ///< [px] disparity error of each pixel alone
  double field_cell_px = 16.0;       ///< [px] grid spacing of the two smooth fields
  double disparity_step_px = 0.125;  ///< [px] the disparity is rounded to multiples of this
  int bleed_px = 2;                  ///< [px] reach of the nearer depth at an edge
  double bleed_probability = 0.5;    ///< chance that a pixel within that reach reads it
};

/// Sensor model of the Kinect-like RGB-D camera.
struct SensorParams {
  int width = 640, height = 480;                ///< [px]
  double fx = 525.0, fy = 525.0;                ///< [px]
  double cx = 319.5, cy = 239.5;                ///< [px]
  double depth_scale = 5000.0;                  ///< depth PNG units per metre
  double depth_sigma_quadratic_per_m = 1.4e-3;  ///< [1/m] sigma_d = this * d^2 + constant
  double depth_sigma_constant_m = 1.0e-3;       ///< [m]
  double min_depth_m = 0.3;                     ///< [m] nearer surfaces read 0 (no depth)
  double max_depth_m = 6.0;                     ///< [m] farther surfaces read 0
  double edge_jump_m = 0.1;                     ///< [m] depth jump to a 4-neighbour = an edge
  double edge_dropout_probability = 0.5;        ///< chance an edge pixel reads 0
  double colour_sigma = 2.0;                    ///< [grey levels] colour noise per channel
  /// Lens distortion of the colour and depth images (plumb_bob, core/camera.h): the scene is
  /// rendered through an ideal pinhole camera with a margin and warped into the distorted image
  /// with OpenCV's cv::undistortPoints (independent of PinholeCamera::Distort/Undistort).
  Distortion distortion;
  StructuredLightParams structured_light;  ///< off: Gaussian depth noise per pixel (above)
};

/// Everything that defines a synthetic sequence.
struct Scenario {
  std::string name;
  uint32_t seed = 1;              ///< textures, furniture jitter, sensor noise
  int frames = 300;               ///< default number of frames
  double fps = 30.0;              ///< [Hz]
  double start_stamp_s = 1000.0;  ///< [s] stamp of frame 0
  /// [s] > 0: the camera and every moving thing repeat with this period, so frame
  /// period_s * fps (an integer, = frames) shows the geometry of frame 0 and the frames can be
  /// replayed in a loop without a jump (`loop`); 0: not periodic.
  double period_s = 0.0;
  RoomParams room;
  SensorParams sensor;
  CameraMotionParams camera;
  std::vector<WalkerParams> walkers;   ///< mask ids 1..W
  std::vector<MovingBoxParams> boxes;  ///< mask ids W+1..W+B
  std::vector<SheetParams> sheets;     ///< mask ids W+B+1..
};

/// Names accepted by MakeScenario(), with a one-line description each.
std::vector<std::pair<std::string, std::string>> ScenarioNames();

/// Builds the named scenario; throws std::invalid_argument for an unknown name.
Scenario MakeScenario(const std::string& name, uint32_t seed);

/// The tracker's depth model for `sensor`: its Gaussian depth noise (sigma_d = a d^2 + b,
/// independent per pixel), which WriteCameraYaml states in camera.yaml. A structured-light sensor
/// leaves `depth_noise` unchanged: like a real camera, it is modelled by depth_noise's defaults.
void UseSensorDepthNoise(const SensorParams& sensor, DepthNoiseConfig* depth_noise);

/// The static part of the scene (room and furniture), which depends on the seed only.
SceneGeometry BuildStaticScene(const RoomParams& room, uint32_t seed);

}  // namespace synth
}  // namespace dslam
