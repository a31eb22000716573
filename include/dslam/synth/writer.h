#pragma once
// Writing synthetic sequences in the TUM RGB-D layout (read back by TumDataset):
//   camera.yaml, rgb.txt + rgb/<stamp>.png (8-bit BGR), depth.txt + depth/<stamp>.png (16-bit,
//   depth_scale units per metre), groundtruth.txt (T_world_camera, TUM format),
//   mask.txt + mask/<stamp>.png (16-bit object id, 0 = static),
//   depth_true.txt + depth_true/<stamp>.png (16-bit noise-free depth, same scale as depth/),
//   objects.txt (object_truth.h: per frame and visible moving object
//   `timestamp id x y z vx vy vz pixel_share`, world frame),
//   dynamic_coverage.txt (`timestamp fraction_of_pixels_on_moving_objects`), synth_info.txt.

#include <functional>
#include <string>

#include <opencv2/core.hpp>

#include "dslam/synth/sequence.h"

namespace dslam {
namespace synth {

/// Statistics of a written sequence.
struct WriteSummary {
  int frames = 0;
  double seconds = 0.0;        ///< [s] wall time of rendering and writing
  double coverage_mean = 0.0;  ///< mean fraction of pixels on moving objects
  double coverage_min = 0.0;
  double coverage_max = 0.0;
};

/// Writes camera.yaml for the sensor (its distortion, groundtruth_correction none).
void WriteCameraYaml(const std::string& path, const SensorParams& sensor);

/// Renders frames [0, frames) of `sequence` into `folder` (created if missing). `progress` is
/// called after each frame with (frames done, frames). Throws std::runtime_error on I/O errors.
WriteSummary WriteSequence(const SyntheticSequence& sequence, const std::string& folder, int frames,
                           const std::function<void(int, int)>& progress = {});

/// A half-size panel: colour | depth (colourised, black = no depth) | mask (one colour per id).
cv::Mat MakePreviewPanel(const SyntheticFrame& frame, double max_depth_m);

/// The noise-free depth `depth_true_m` (CV_32FC1 [m]) as written to depth_true/: CV_16UC1,
/// round(depth * depth_scale) [units], 0 where nothing was hit or beyond 65535 units.
cv::Mat NoiseFreeDepthUnits(const cv::Mat& depth_true_m, double depth_scale);

/// Formats a stamp as in the file names and lists ("%.6f").
std::string FormatStamp(double stamp_s);

}  // namespace synth
}  // namespace dslam
