#pragma once
// Motion blur of the synthetic colour camera (ExposureParams in camera_motion.h). The colour image
// of a frame at time t is the rounded mean of N sub-frame renders taken at the centres of N equal
// slices of the exposure [t - e / 2, t + e / 2]. N is chosen from the camera motion: the smallest
// odd N with path / N <= max_step_px, capped at max_subframes, where path [px] is the longest image
// path of a scene point seen at t while the camera moves through the exposure. N is odd so that
// the middle sub-frame is the sharp render at t itself. Depth, mask and ground truth are not
// blurred: they are those of time t (the exposure's middle). The motion of moving objects during
// the exposure is rendered (objects are placed at each sub-frame's time) but does not enter N.

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/core/camera.h"
#include "dslam/synth/camera_motion.h"

namespace dslam {
namespace synth {

/// T_world_camera at `segments` + 1 equally spaced times from t_s - exposure_s / 2 to
/// t_s + exposure_s / 2 [s] (times relative to the start of the sequence).
std::vector<Eigen::Isometry3d> ExposurePath(const CameraMotionParams& motion, double t_s,
                                            uint32_t seed, double exposure_s, int segments);

/// [px] Longest image path of the surfaces seen in `depth_m` (CV_32FC1 depth along the optical
/// axis [m] at T_world_camera_ref; 0 = nothing hit, taken as infinitely far) while the camera
/// follows `T_world_camera_path`: per pixel of a grid with spacing `pixel_stride` [px] (plus the
/// last row and column), the sum of the distances between its projections in consecutive poses of
/// the path; the maximum over the grid. Pixels that fall behind a camera of the path are skipped.
double MaxImagePathPx(const PinholeCamera& camera, const cv::Mat& depth_m,
                      const Eigen::Isometry3d& T_world_camera_ref,
                      const std::vector<Eigen::Isometry3d>& T_world_camera_path, int pixel_stride);

/// Number of sub-frames for an image path of `path_px` [px]: the smallest odd N >= path_px /
/// exposure.max_step_px (at least 1), at most the largest odd number <= exposure.max_subframes.
int SubframeCount(double path_px, const ExposureParams& exposure);

/// [s] Offsets of the `n` sub-frame times from the frame's time: (k + 0.5) / n * exposure_s -
/// exposure_s / 2 for k = 0..n-1; for odd n the middle one, k = (n - 1) / 2, is exactly 0.
std::vector<double> SubframeOffsets(double exposure_s, int n);

/// Per-channel mean of CV_8UC3 images of equal size, rounded half up (exact integer arithmetic).
cv::Mat MeanColour(const std::vector<cv::Mat>& images);

}  // namespace synth
}  // namespace dslam
