#pragma once
// An SE(3) pose graph over keyframes: a plain description (independent of the Map) of the
// keyframe poses and of relative-pose measurements between them, and its optimisation with
// Ceres (src/loop_closing/pose_graph.cpp). Poses are T_world_camera: they map points of the
// keyframe's optical frame into the world.

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dslam {

/// 6x6 information of a relative-pose measurement [1/rad^2, 1/m^2, mixed off the diagonal], in
/// the residual's order: rotation error (angle-axis, 3, rad), then translation error (3, m).
using PoseGraphInformation = Eigen::Matrix<double, 6, 6>;

/// One keyframe of the graph.
struct PoseGraphNode {
  /// Pose of the keyframe's optical frame in the world [m]; the initial guess of the solve.
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  bool fixed = false;  ///< the solve keeps this pose (at least one node of a graph is fixed)
};

/// Where an edge's measurement comes from.
enum class PoseGraphEdgeKind { kSpanningTree, kCovisibility, kLoop };

/// A relative-pose measurement between keyframes a and b.
struct PoseGraphEdge {
  int id_a = -1;  ///< keyframe id of the first node
  int id_b = -1;  ///< keyframe id of the second node
  /// Measured T_a_b = T_world_a^-1 T_world_b: maps points of b's optical frame into a's [m].
  Eigen::Isometry3d T_a_b = Eigen::Isometry3d::Identity();
  /// Information of the residual (PoseGraphResidual); must be symmetric positive definite.
  PoseGraphInformation information = PoseGraphInformation::Identity();
  PoseGraphEdgeKind kind = PoseGraphEdgeKind::kSpanningTree;
};

/// Nodes by keyframe id, and the edges between them.
struct PoseGraph {
  std::map<int, PoseGraphNode> nodes;
  std::vector<PoseGraphEdge> edges;
};

/// How OptimisePoseGraph solves.
struct PoseGraphOptions {
  int max_iterations = 100;  ///< Levenberg-Marquardt iterations at most
  int num_threads = 1;       ///< Ceres threads; 1 gives the same result on every run
};

/// The corrected poses and the solver's account of the solve.
struct PoseGraphResult {
  bool success = false;  ///< Ceres reports the solution usable (converged or out of iterations)
  /// Every node's pose after the solve [m]; a fixed node's is its input, bit for bit.
  std::map<int, Eigen::Isometry3d> T_world_camera;
  int iterations = 0;         ///< Levenberg-Marquardt steps, successful and unsuccessful
  double initial_cost = 0.0;  ///< [-] 1/2 sum of squared whitened residuals
  double final_cost = 0.0;    ///< [-] the same after the solve
};

/// The node of keyframe `id`. Throws std::invalid_argument naming the id when the graph has none.
const PoseGraphNode& FindPoseGraphNode(const PoseGraph& graph, int id);

/// An edge a -> b of `kind` whose measurement is the nodes' present relative pose
/// T_a_b = T_world_a^-1 T_world_b (e.g. spanning-tree and covisibility edges taken from the
/// keyframe poses before a loop correction). Throws as FindPoseGraphNode.
PoseGraphEdge MakePoseGraphEdge(const PoseGraph& graph, int id_a, int id_b, PoseGraphEdgeKind kind,
                                const PoseGraphInformation& information);

/// Information of a measurement with independent errors: rotation standard deviation
/// `sigma_rotation_rad` [rad] about each axis and translation `sigma_translation_m` [m] along
/// each axis. Both must be positive.
PoseGraphInformation PoseGraphEdgeInformation(double sigma_translation_m,
                                              double sigma_rotation_rad);

/// The residual of one edge at poses T_world_a and T_world_b [m]: with the error
/// E = T_a_b^-1 T_world_a^-1 T_world_b, the 6-vector (angle-axis of E's rotation [rad], E's
/// translation [m]) multiplied by the upper Cholesky factor S of the information (S^T S = Info).
/// Zero when the poses agree with the measurement.
Eigen::Matrix<double, 6, 1> PoseGraphResidual(const PoseGraphEdge& edge,
                                              const Eigen::Isometry3d& T_world_a,
                                              const Eigen::Isometry3d& T_world_b);

/// Minimises the sum of squared PoseGraphResidual over the edges, each node's pose a quaternion
/// on Ceres' Eigen quaternion manifold and a translation, the fixed nodes held. Nodes without
/// edges keep their pose. Throws std::invalid_argument when no node is fixed, when an edge names
/// a node missing from the graph or joins a node to itself (the message names the id), when an
/// edge's information is not positive definite (it names the edge's ids) or when an option is
/// out of range.
PoseGraphResult OptimisePoseGraph(const PoseGraph& graph, const PoseGraphOptions& options = {});

}  // namespace dslam
