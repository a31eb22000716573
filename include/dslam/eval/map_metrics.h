#pragma once
// The static map against synthetic truth. The reference is built from the noise-free depth
// (depth_true/ of dslam_synth), the masks and the ground-truth poses of every frame: pixels of the
// static world (mask 0) and pixels of moving objects (mask != 0) are back-projected into the world
// and voxel-downsampled (one centroid per voxel) into the static reference surface and the cloud
// of where moving objects were (any frame). A map (points in the world frame) is then scored:
// - ghost share: map points within radius_m of a moving-object point and farther than radius_m
//   from every static reference point / all map points;
// - static coverage: static reference points within radius_m of a map point / all static
//   reference points;
// - static share: map points within radius_m of a static reference point / all map points.
// Neighbour tests are exact (RadiusIndex, voxel_index.h).

#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/core/camera.h"
#include "dslam/eval/voxel_index.h"

namespace dslam {

/// Parameters of the map measurement.
struct MapMetricsOptions {
  double radius_m = 0.05;  ///< [m] distance of "within" and "farther than"
  double voxel_m = 0.01;   ///< [m] voxel edge of the reference clouds
  int pixel_stride = 2;    ///< [px] every pixel_stride-th pixel of every pixel_stride-th row
  int frame_stride = 1;    ///< every frame_stride-th frame of the sequence
  /// [m] true depths outside [min_depth_m, max_depth_m] are left out (the range dslam_synth's
  /// sensor measures: SensorParams min_depth_m, max_depth_m)
  double min_depth_m = 0.3;
  double max_depth_m = 6.0;
};

/// The reference clouds [m], world frame.
struct MapReference {
  std::vector<Eigen::Vector3d> static_points;   ///< static surface, one point per voxel
  std::vector<Eigen::Vector3d> dynamic_points;  ///< where moving objects were, one per voxel
  int frames = 0;                               ///< frames that contributed
};

/// Accumulates frames into the reference clouds.
class MapReferenceBuilder {
 public:
  /// Throws std::invalid_argument for a voxel size that is not positive or a stride below 1.
  explicit MapReferenceBuilder(const MapMetricsOptions& options);

  /// Adds one frame: `depth_true_m` CV_32FC1 [m] (0 = nothing), `mask` CV_16UC1 of the same
  /// size (0 = static), `camera` (its distortion is undone before back-projection), and the
  /// ground-truth pose T_world_camera. Throws std::invalid_argument on mismatched images.
  void AddFrame(const cv::Mat& depth_true_m, const cv::Mat& mask, const PinholeCamera& camera,
                const Eigen::Isometry3d& T_world_camera);

  /// The clouds accumulated so far.
  MapReference Build() const;

 private:
  MapMetricsOptions options_;
  VoxelDownsampler static_, dynamic_;
  int frames_ = 0;
};

/// Builds the reference of a dslam_synth folder: depth_true.txt, mask.txt, groundtruth.txt and
/// camera.yaml (depth_scale), every options.frame_stride-th entry of depth_true.txt with the mask
/// and pose of the same stamp (within 1e-4 s). Throws std::runtime_error when a file is missing
/// or unreadable, or a stamp has no mask or pose.
MapReference LoadMapReference(const std::string& folder, const MapMetricsOptions& options);

/// Scores of a map against a reference.
struct MapMetrics {
  size_t map_points = 0;          ///< finite map points scored
  size_t ghost_points = 0;        ///< near a moving-object point, far from the static surface
  size_t near_static_points = 0;  ///< map points within radius_m of the static surface
  size_t static_reference_points = 0;
  size_t dynamic_reference_points = 0;
  size_t covered_static_points = 0;  ///< static reference points within radius_m of the map
  double ghost_share = 0.0;          ///< ghost_points / map_points (0 for an empty map)
  double static_share = 0.0;         ///< near_static_points / map_points (0 for an empty map)
  double static_coverage = 0.0;      ///< covered / static reference points (0 when none)
};

/// Scores `map_world_m` (world frame [m]; non-finite points are left out) against `reference`.
MapMetrics EvaluateMap(const std::vector<Eigen::Vector3d>& map_world_m,
                       const MapReference& reference, double radius_m);

}  // namespace dslam
