#pragma once
// A synthetic RGB-D sequence rendered frame by frame in-process (tests, soak tests) or written to a
// TUM-layout folder (writer.h). Frame i is a pure function of (scenario, seed, i): frames can
// be rendered in any order and always come out byte-identical.

#include <memory>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/core/camera.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/synth/scenario.h"

namespace dslam {
namespace synth {

/// One rendered frame with its ground truth.
struct SyntheticFrame {
  int index = 0;
  RgbdFrame frame;       ///< noisy colour and depth exactly as written to / read from PNG
  cv::Mat depth_units;   ///< CV_16UC1 depth PNG content (depth_scale units per metre)
  cv::Mat depth_true_m;  ///< CV_32FC1 noise-free depth [m] (0 = nothing hit)
  cv::Mat colour_clean;  ///< CV_8UC3 noise-free colour
  cv::Mat mask;          ///< CV_16UC1 moving-object id per pixel, 0 = static
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();  ///< ground truth
  double dynamic_fraction = 0.0;  ///< fraction of pixels with mask != 0
  /// Colour renders averaged into colour_clean (motion blur, motion_blur.h); 1 = sharp.
  int colour_subframes = 1;
  /// [px] longest image path during the exposure of the surfaces seen at the frame's time, taken
  /// as static (MaxImagePathPx in motion_blur.h); 0 without exposure.
  double blur_path_px = 0.0;
};

/// Renders the frames of one scenario.
class SyntheticSequence {
 public:
  explicit SyntheticSequence(Scenario scenario);

  const Scenario& scenario() const { return scenario_; }
  /// The camera of the frames, with the sensor's distortion.
  const std::shared_ptr<const PinholeCamera>& camera() const { return camera_; }
  /// The ideal pinhole camera the scene is rendered through: camera() itself without
  /// distortion; with distortion, camera()'s focal lengths on an image larger by a margin that
  /// covers every distorted pixel (its principal point moved by the margin).
  const std::shared_ptr<const PinholeCamera>& render_camera() const { return render_camera_; }

  /// [s] stamp of frame `index`: start + index / fps, rounded to whole microseconds so it
  /// survives the "%.6f" text of rgb.txt and groundtruth.txt exactly.
  double StampOf(int index) const;

  /// Ground-truth T_world_camera of frame `index`.
  Eigen::Isometry3d PoseOf(int index) const;

  /// All geometry (static room and moving things) at the time of frame `index`.
  SceneGeometry GeometryAt(int index) const;

  /// All geometry at `t_s` [s] after the start of the sequence (sub-frames of the exposure).
  SceneGeometry GeometryAtTime(double t_s) const;

  /// Renders frame `index` (any index >= 0; beyond scenario().frames the motions continue). With
  /// scenario().camera.exposure.exposure_s > 0 the colour is motion-blurred (motion_blur.h); depth,
  /// mask and pose are those of the frame's time, the middle of the exposure.
  SyntheticFrame RenderFrame(int index) const;

 private:
  /// With distortion: the images of render_camera() warped into camera()'s (colour bilinear,
  /// depth and mask nearest; beyond the rendered image: no depth, black, static).
  void Distort(SyntheticFrame* frame) const;

  Scenario scenario_;
  std::shared_ptr<const PinholeCamera> camera_;
  std::shared_ptr<const PinholeCamera> render_camera_;
  cv::Mat map_u_, map_v_;  ///< CV_32FC1: per pixel of camera(), where it is in render_camera()'s
  SceneGeometry static_scene_;
};

/// Applies the sensor model to noise-free images of frame `index`: depth noise with
/// sigma = a d^2 + b or, when sensor.structured_light is enabled, a structured-light camera's
/// disparity errors and edge bleeding; range limits, dropouts at depth edges, 16-bit
/// quantisation, colour noise.
/// Noise comes from a counter-based generator keyed by (seed, index, pixel).
void ApplySensorModel(const SensorParams& sensor, uint32_t seed, int index,
                      const cv::Mat& colour_clean, const cv::Mat& depth_true_m, cv::Mat* colour,
                      cv::Mat* depth_units);

}  // namespace synth
}  // namespace dslam
