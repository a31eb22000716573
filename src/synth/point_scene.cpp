#include "dslam/synth/point_scene.h"

#include <cmath>
#include <random>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

namespace dslam {
namespace synth {
namespace {

// A point on a wall, the floor or in the room volume (x in [-2, 2], y in [-1.2, 1.2] with the
// floor at y = 1.2 (camera y points down), z in [2, 5]).
Eigen::Vector3d RoomPoint(std::mt19937* rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double x = -2.0 + 4.0 * u(*rng), y = -1.2 + 2.4 * u(*rng), z = 2.0 + 3.0 * u(*rng);
  const double pick = u(*rng);
  if (pick < 0.3) return {x, y, 5.0};                                          // back wall
  if (pick < 0.5) return {pick < 0.4 ? -2.0 : 2.0, y, 3.5 + 0.5 * (z - 2.0)};  // side walls
  if (pick < 0.75) return {x, 1.2, z};                                         // floor
  return {x, y, z};                                                            // clutter
}

Eigen::Isometry3d CameraPose(int k, const PointSceneOptions& o) {
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  T_world_camera.translation() = k * o.camera_step_m * Eigen::Vector3d(1.0, 0.3, 0.5);
  T_world_camera.linear() =
      (Eigen::AngleAxisd(k * o.camera_step_rad, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(0.5 * k * o.camera_step_rad, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  return T_world_camera.inverse();
}

Eigen::Vector3d ClusterOffset(int k, const PointSceneOptions& o) {
  if (o.frames < 2) return Eigen::Vector3d::Zero();
  if (o.jump) return k >= o.frames / 2 ? o.cluster_motion : Eigen::Vector3d::Zero();
  return o.cluster_motion * (static_cast<double>(k) / (o.frames - 1));
}

}  // namespace

Eigen::Matrix3d DepthNoiseCovariance(const Eigen::Vector3d& y_camera, double focal_px,
                                     double sigma_px, double depth_coeff) {
  const double d = y_camera.z();
  const double sigma_along = depth_coeff * d * d;
  const double sigma_across = sigma_px * d / focal_px;
  const Eigen::Vector3d ray = y_camera.normalized();
  const Eigen::Matrix3d along = ray * ray.transpose();
  return sigma_across * sigma_across * (Eigen::Matrix3d::Identity() - along) +
         sigma_along * sigma_along * along;
}

PointScene MakePointScene(const PointSceneOptions& o) {
  std::mt19937 rng(o.seed);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Eigen::Vector3d> truth;  // world positions at frame 0
  PointScene scene;
  for (int i = 0; i < o.static_points; ++i) truth.push_back(RoomPoint(&rng));
  const Eigen::Vector3d centre(0.3, 0.1, o.cluster_depth_m);
  for (int i = 0; i < o.dynamic_points; ++i) {
    truth.push_back(centre + Eigen::Vector3d(0.5 * u(rng), 1.7 * u(rng), 0.3 * u(rng)));
  }
  scene.is_dynamic.assign(truth.size(), false);
  for (int i = o.static_points; i < static_cast<int>(truth.size()); ++i) scene.is_dynamic[i] = true;

  CorrelationInput& in = scene.input;
  in.points_world.resize(truth.size());
  for (int k = 0; k < o.frames; ++k) in.T_camera_world.push_back(CameraPose(k, o));
  for (int k = 0; k < o.frames; ++k) {
    for (int i = 0; i < static_cast<int>(truth.size()); ++i) {
      const Eigen::Vector3d p =
          truth[i] + (scene.is_dynamic[i] ? ClusterOffset(k, o) : Eigen::Vector3d::Zero());
      PointObservation obs;
      obs.point = i;
      obs.frame = k;
      const Eigen::Vector3d y = in.T_camera_world[k] * p;
      obs.covariance = DepthNoiseCovariance(y, o.focal_px, o.sigma_px, o.depth_coeff);
      const Eigen::Vector3d n(normal(rng), normal(rng), normal(rng));
      obs.y_camera = y + obs.covariance.llt().matrixL() * n;
      if (k == 0) in.points_world[i] = in.T_camera_world[0].inverse() * obs.y_camera;
      in.observations.push_back(obs);
    }
  }
  return scene;
}

}  // namespace synth
}  // namespace dslam
