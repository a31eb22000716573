#pragma once
// A ring of keyframes with known poses for the pose-graph tests: odometry edges between
// consecutive keyframes whose measurements carry noise and a drift that accumulates along the
// ring, the nodes at the poses chained from them (the first at its true pose, fixed), and one
// loop edge from the last keyframe to the first with the true relative pose.

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "dslam/loop_closing/pose_graph.h"

namespace dslam {
namespace test {

struct RingOptions {
  int keyframes = 40;
  double circumference_m = 8.0;
  unsigned seed = 1;
  double noise_translation_m = 0.002;  ///< per axis, per odometry edge
  double noise_rotation_rad = 0.0005;  ///< per axis, per odometry edge
  double drift_yaw_rad = 0.0;          ///< added to every odometry edge about its z axis
  /// Added to every odometry translation [m], in the edge's first frame.
  Eigen::Vector3d drift_translation_m = Eigen::Vector3d::Zero();
  double sigma_translation_m = 0.01;  ///< edge information (odometry and loop)
  double sigma_rotation_rad = 0.002;
};

struct Ring {
  std::vector<Eigen::Isometry3d> T_world_camera_true;  ///< by keyframe id
  PoseGraph graph;
};

/// The drifting ring of the tests: 5 deg of yaw and 0.27 m of height added over the ring's
/// odometry; the chained poses end about 0.3 m and 5 deg off.
inline RingOptions DriftingRingOptions() {
  RingOptions options;
  options.drift_yaw_rad = 5.0 * M_PI / 180.0 / 39;
  options.drift_translation_m = Eigen::Vector3d(0.0, 0.0, 0.007);
  return options;
}

/// Keyframe k on a circle in the x-y plane, with a small height and roll wave (so not planar).
inline Eigen::Isometry3d RingPose(int k, const RingOptions& options) {
  const double theta = 2.0 * M_PI * k / options.keyframes;
  const double radius_m = options.circumference_m / (2.0 * M_PI);
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  T_world_camera.linear() = (Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(0.1 * std::sin(theta), Eigen::Vector3d::UnitX()))
                                .matrix();
  T_world_camera.translation() = Eigen::Vector3d(
      radius_m * std::cos(theta), radius_m * std::sin(theta), 0.1 * std::sin(2 * theta));
  return T_world_camera;
}

/// A rigid motion with rotation vector `w` [rad] and translation `t` [m].
inline Eigen::Isometry3d Motion(const Eigen::Vector3d& w, const Eigen::Vector3d& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  if (w.norm() > 0) T.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()).matrix();
  T.translation() = t;
  return T;
}

/// The odometry measurement of edge k -> k+1: truth, drifted, with noise.
inline Eigen::Isometry3d OdometryMeasurement(const Eigen::Isometry3d& T_a_b_true,
                                             const RingOptions& options, std::mt19937* rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Isometry3d T_a_b = T_a_b_true;
  T_a_b.translation() += options.drift_translation_m;
  T_a_b = T_a_b * Motion(Eigen::Vector3d(0, 0, options.drift_yaw_rad), Eigen::Vector3d::Zero());
  const Eigen::Vector3d w(normal(*rng), normal(*rng), normal(*rng));
  const Eigen::Vector3d t(normal(*rng), normal(*rng), normal(*rng));
  return T_a_b * Motion(w * options.noise_rotation_rad, t * options.noise_translation_m);
}

inline Ring MakeRing(const RingOptions& options) {
  Ring ring;
  std::mt19937 rng(options.seed);
  const PoseGraphInformation information =
      PoseGraphEdgeInformation(options.sigma_translation_m, options.sigma_rotation_rad);
  for (int k = 0; k < options.keyframes; ++k)
    ring.T_world_camera_true.push_back(RingPose(k, options));
  ring.graph.nodes[0] = {ring.T_world_camera_true[0], true};
  for (int k = 0; k + 1 < options.keyframes; ++k) {
    PoseGraphEdge edge;
    edge.id_a = k;
    edge.id_b = k + 1;
    edge.T_a_b = OdometryMeasurement(
        ring.T_world_camera_true[k].inverse() * ring.T_world_camera_true[k + 1], options, &rng);
    edge.information = information;
    edge.kind = PoseGraphEdgeKind::kSpanningTree;
    ring.graph.edges.push_back(edge);
    ring.graph.nodes[k + 1] = {ring.graph.nodes[k].T_world_camera * edge.T_a_b, false};
  }
  PoseGraphEdge loop;
  loop.id_a = options.keyframes - 1;
  loop.id_b = 0;
  loop.T_a_b = ring.T_world_camera_true.back().inverse() * ring.T_world_camera_true[0];
  loop.information = information;
  loop.kind = PoseGraphEdgeKind::kLoop;
  ring.graph.edges.push_back(loop);
  return ring;
}

/// Translation [m] and rotation [rad] errors of a pose against the truth.
struct PoseError {
  double translation_m = 0.0;
  double rotation_rad = 0.0;
};

inline PoseError ErrorOf(const Eigen::Isometry3d& T_world_camera,
                         const Eigen::Isometry3d& T_world_camera_true) {
  const Eigen::Isometry3d E = T_world_camera_true.inverse() * T_world_camera;
  return {(T_world_camera.translation() - T_world_camera_true.translation()).norm(),
          Eigen::AngleAxisd(E.rotation()).angle()};
}

/// The largest errors over the keyframes of `T_world_camera` (by id) against the ring's truth.
inline PoseError MaxError(const std::map<int, Eigen::Isometry3d>& T_world_camera,
                          const Ring& ring) {
  PoseError worst;
  for (const auto& [id, T] : T_world_camera) {
    const PoseError e = ErrorOf(T, ring.T_world_camera_true[id]);
    worst.translation_m = std::max(worst.translation_m, e.translation_m);
    worst.rotation_rad = std::max(worst.rotation_rad, e.rotation_rad);
  }
  return worst;
}

/// The nodes' poses of a graph, by id.
inline std::map<int, Eigen::Isometry3d> NodePoses(const PoseGraph& graph) {
  std::map<int, Eigen::Isometry3d> poses;
  for (const auto& [id, node] : graph.nodes) poses[id] = node.T_world_camera;
  return poses;
}

}  // namespace test
}  // namespace dslam
