#pragma once
// Coloured point clouds of the static map: the type, PCD files (x y z rgb, the fields PCL's
// PointXYZRGB writes), and a keyframe's depth as such a cloud, ready to be fused: sampled every
// few pixels, without the pixels of moving objects, voxel filtered.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "dslam/backend/keyframe_observer.h"
#include "dslam/core/features_config.h"
#include "dslam/core/map_config.h"
#include "dslam/core/objects_config.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/mapping/dynamic_mask.h"

namespace dslam {

/// One map point with its colour.
struct ColouredPoint {
  Eigen::Vector3f p = Eigen::Vector3f::Zero();  ///< [m] position, in the cloud's frame
  uint8_t r = 0, g = 0, b = 0;                  ///< colour, 0-255 per channel
};

/// A cloud of coloured points; its frame is stated where it is produced.
using ColouredCloud = std::vector<ColouredPoint>;

/// Writes `cloud` as a binary PCD file with fields x y z rgb (metres; rgb packed as PCL's
/// PointXYZRGB). Throws std::runtime_error naming `path` when it cannot be written.
void WritePcd(const std::string& path, const ColouredCloud& cloud);

/// Reads a PCD file with fields x y z and, when present, rgb. Throws std::runtime_error naming
/// `path` when it cannot be read.
ColouredCloud ReadPcd(const std::string& path);

/// What BackProjectKeyFrame samples and how it thins the result.
struct BackProjection {
  int pixel_step = 4;          ///< [px] every pixel_step-th pixel in u and v
  double min_depth_m = 0.3;    ///< [m] nearer depths are skipped
  double max_depth_m = 4.0;    ///< [m] farther depths are skipped
  double voxel_size_m = 0.05;  ///< [m] voxel grid (PCL VoxelGrid) of the result; 0: none

  /// The static map's sampling: map.pixel_step, the depth noise model's depth range and
  /// map.voxel_size_m.
  static BackProjection Of(const MapConfig& map, const DepthNoiseConfig& depth_noise) {
    return {map.pixel_step, depth_noise.min_depth_m, depth_noise.max_depth_m, map.voxel_size_m};
  }
};

/// The pixels of `frame` with a depth in range and `mask` 0 (`mask` CV_8UC1 of the image size,
/// or empty: none masked), back-projected (undistorted first) into the optical frame [m],
/// coloured from `frame.colour` (grey images: r = g = b), one point per voxel (centroid and mean
/// colour of the voxel's points).
ColouredCloud BackProjectKeyFrame(const RgbdFrame& frame, const cv::Mat& mask,
                                  const BackProjection& options);

/// Which pixels of `keyframe` belong to moving objects, so that the static map leaves them out:
/// CV_8UC1 of its images' size, 255 on them, 0 elsewhere. The per-pixel dynamic mask of
/// dynamic_mask.h (ComputeDynamicMask of the keyframe's frame, pose and point labels), each
/// cell's label on its pixels; pixels beyond the last whole cell are 0.
cv::Mat DynamicPixelMask(const KeyFrameRecord& keyframe, const DynamicMaskConfig& config);

/// `mask`'s cells as pixels: CV_8UC1 of `image_size`, 255 on masked cells, 0 elsewhere (pixels
/// beyond the last whole cell are 0).
cv::Mat PixelMask(const DynamicMask& mask, const cv::Size& image_size);

/// The pixels of `frame` on `mask` (moving things now) with a depth in range, back-projected
/// into the optical frame [m] as BackProjectKeyFrame does: the points of the people in view.
ColouredCloud BackProjectMasked(const RgbdFrame& frame, const DynamicMask& mask,
                                const BackProjection& options);

}  // namespace dslam
