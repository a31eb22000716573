#pragma once
// A keyframe's depth as coloured points in its optical frame, ready to be fused into the static
// map: sampled every few pixels, without masked pixels, voxel filtered.

#include <opencv2/core.hpp>

#include "dslam/core/rgbd_frame.h"
#include "dslam/mapping/coloured_cloud.h"

namespace dslam {

/// What BackProjectKeyFrame samples and how it thins the result.
struct BackProjection {
  int pixel_step = 4;          ///< [px] every pixel_step-th pixel in u and v
  double min_depth_m = 0.3;    ///< [m] nearer depths are skipped
  double max_depth_m = 4.0;    ///< [m] farther depths are skipped
  double voxel_size_m = 0.05;  ///< [m] voxel grid (PCL VoxelGrid) of the result; 0: none
};

/// The pixels of `frame` with a depth in range and `mask` 0 (`mask` CV_8UC1 of the image size,
/// or empty: none masked), back-projected (undistorted first) into the optical frame [m],
/// coloured from `frame.colour` (grey images: r = g = b), one point per voxel (centroid and mean
/// colour of the voxel's points).
ColouredCloud BackProjectKeyFrame(const RgbdFrame& frame, const cv::Mat& mask,
                                  const BackProjection& options);

}  // namespace dslam
