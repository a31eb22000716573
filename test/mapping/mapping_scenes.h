#pragma once
// Keyframes of known geometry for the static map's tests: a camera whose sampled pixels never
// fall on a voxel boundary, and depth images built from a per-pixel function.

#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/backend/keyframe_observer.h"
#include "dslam/core/config.h"

namespace dslam {
namespace test {

// 640x480, f = 505 px: at 2.02 m depth one pixel spans 4 mm, and with the principal point at
// .25 px the samples of pixel_step 4 (pixels 2, 6, ...) lie at odd millimetres, never on the
// boundaries of 5 cm voxels (even millimetres).
inline std::shared_ptr<const PinholeCamera> TestCamera() {
  return std::make_shared<PinholeCamera>(640, 480, 505.0, 505.0, 320.25, 240.25);
}
constexpr double kPlaneDepthM = 2.02;

/// A keyframe with depth `depth_m(u, v)` [m] and colour BGR (10, 20, 30), at `T_world_camera`.
inline KeyFrameRecord MakeKeyFrame(
    int id, const std::function<float(int, int)>& depth_m,
    const Eigen::Isometry3d& T_world_camera = Eigen::Isometry3d::Identity()) {
  KeyFrameRecord keyframe;
  keyframe.id = id;
  keyframe.T_world_camera = T_world_camera;
  keyframe.frame.stamp_s = id;
  keyframe.frame.camera = TestCamera();
  keyframe.frame.colour = cv::Mat(480, 640, CV_8UC3, cv::Scalar(10, 20, 30));
  keyframe.frame.depth_m = cv::Mat(480, 640, CV_32FC1);
  for (int v = 0; v < 480; ++v) {
    for (int u = 0; u < 640; ++u) keyframe.frame.depth_m.at<float>(v, u) = depth_m(u, v);
  }
  return keyframe;
}

/// A wall at `depth` [m] everywhere.
inline std::function<float(int, int)> Wall(float depth) {
  return [depth](int, int) { return depth; };
}

/// A wall at `wall` [m] with a box at `box` [m] over pixels [u0, u1) x [v0, v1).
inline std::function<float(int, int)> WallWithBox(float wall, float box, int u0, int u1, int v0,
                                                  int v1) {
  return [=](int u, int v) { return u >= u0 && u < u1 && v >= v0 && v < v1 ? box : wall; };
}

/// The map's configuration of the tests: 5 cm voxels, pixel_step 4, depths up to 4 m, no mask
/// unless asked.
inline Config MapTestConfig() {
  Config config;
  config.map.voxel_size_m = 0.05;
  config.map.pixel_step = 4;
  config.depth_noise.max_depth_m = 4.0;
  return config;
}

/// Poses of `keyframes` as a window (KeyFramePose list).
inline std::vector<KeyFramePose> WindowOf(const std::vector<KeyFrameRecord>& keyframes) {
  std::vector<KeyFramePose> window;
  for (const KeyFrameRecord& k : keyframes) window.push_back({k.id, k.T_world_camera});
  return window;
}

}  // namespace test
}  // namespace dslam
