#pragma once
// Ray-casting renderer of the synthetic sequences: per pixel the nearest hit among the scene's
// boxes and triangles, shaded with procedural textures and a fixed directional light. Primitives
// are culled to their projected screen rectangle; rows are rendered in parallel (deterministic:
// every pixel is computed by one thread in a fixed primitive order).

#include <cstdint>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/core/camera.h"
#include "dslam/synth/geometry.h"

namespace dslam {
namespace synth {

/// Noise-free images of one view.
struct RenderedImages {
  cv::Mat colour;   ///< CV_8UC3 BGR, textured and lit
  cv::Mat depth_m;  ///< CV_32FC1 depth along the optical axis [m]; 0 where nothing was hit
  cv::Mat mask;     ///< CV_16UC1 object id of the visible surface (0 = static)
};

/// Renders `scene` seen by `camera` (distortion ignored) at T_world_camera.
RenderedImages RenderScene(const SceneGeometry& scene, const PinholeCamera& camera,
                           const Eigen::Isometry3d& T_world_camera);

/// Result of casting one ray against every primitive (no culling; for tests).
struct PixelHit {
  bool hit = false;
  double depth_m = 0.0;    ///< [m] along the optical axis
  uint16_t object_id = 0;  ///< id of the nearest primitive's object
};

/// Casts the ray of pixel (u, v) [px] through all primitives of `scene`, brute force.
PixelHit CastPixelRay(const SceneGeometry& scene, const PinholeCamera& camera,
                      const Eigen::Isometry3d& T_world_camera, double u, double v);

}  // namespace synth
}  // namespace dslam
