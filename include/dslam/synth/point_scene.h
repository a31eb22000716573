#pragma once
// Point scenes for static point determination: room points and a rigid cluster moving by a
// known amount, measured from a moving camera with the RGB-D noise model. The known answer of
// the static-points tests and dslam_spd_bench. Seeded, deterministic.

#include <vector>

#include <Eigen/Core>

#include "dslam/static_points/correlation_problem.h"

namespace dslam {
namespace synth {

/// [m^2] covariance of a point y [m] measured by a depth camera, camera frame: sigma along the
/// viewing ray = depth_coeff * d^2 (Khoshelham; d = y.z()), sigma across = sigma_px * d / focal_px.
Eigen::Matrix3d DepthNoiseCovariance(const Eigen::Vector3d& y_camera, double focal_px,
                                     double sigma_px, double depth_coeff);

/// Layout and motion of a synthetic scene.
struct PointSceneOptions {
  int static_points = 200;  ///< [-] on walls/floor of a room 2-5 m ahead, plus clutter inside
  int dynamic_points = 40;  ///< [-] inside a 0.5 x 1.7 x 0.3 m box ("person") 1.5-2.5 m ahead
  int frames = 2;           ///< [-] camera frames, all observing every point
  /// [m] world displacement of the cluster at the last frame; frame k is displaced by
  /// k / (frames - 1) of it (steady motion). With `jump`, frames >= frames / 2 get all of it.
  Eigen::Vector3d cluster_motion = Eigen::Vector3d(0.1, 0.0, 0.0);
  bool jump = false;              ///< step motion instead of steady motion
  double camera_step_m = 0.03;    ///< [m] camera translation per frame
  double camera_step_rad = 0.01;  ///< [rad] camera rotation per frame
  double focal_px = 525.0;        ///< [px]
  double sigma_px = 1.0;          ///< [px] lateral measurement sigma
  double depth_coeff = 1.4e-3;    ///< [1/m] sigma_d = depth_coeff * d^2
  double cluster_depth_m = 2.0;   ///< [m] depth of the cluster centre
  unsigned seed = 1;              ///< RNG seed (std::mt19937)
};

/// A scene: the problem input plus the ground truth.
struct PointScene {
  CorrelationInput input;        ///< points_world = frame-0 measurements mapped to world
  std::vector<bool> is_dynamic;  ///< per point: member of the moving cluster
};

/// Generates a scene: static points first, then the cluster; measurements y_ik = R_k p_ik + t_k
/// plus Gaussian noise drawn with DepthNoiseCovariance (which is also stored with them).
PointScene MakePointScene(const PointSceneOptions& options);

}  // namespace synth
}  // namespace dslam
