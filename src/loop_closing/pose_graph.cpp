#include "dslam/loop_closing/pose_graph.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <ceres/ceres.h>
#include <ceres/rotation.h>

namespace dslam {
namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

// Upper S with S^T S = information (the 6x6 counterpart of SqrtInformation in core/geometry.h,
// which takes a 3x3 covariance). Throws when the information is not positive definite.
Matrix6d SqrtOfInformation(const PoseGraphEdge& edge) {
  const Eigen::LLT<Matrix6d> llt(edge.information);
  if (llt.info() != Eigen::Success) {
    throw std::invalid_argument("pose graph: the information of edge " + std::to_string(edge.id_a) +
                                " -> " + std::to_string(edge.id_b) + " is not positive definite");
  }
  return llt.matrixU();
}

// PoseGraphResidual for Ceres' automatic derivatives. Parameters: quaternion of R_world_a
// (x y z w), t_world_a, quaternion of R_world_b, t_world_b.
class RelativePoseResidual {
 public:
  RelativePoseResidual(const Eigen::Isometry3d& T_a_b, const Matrix6d& sqrt_information)
      : q_b_a_measured_(Eigen::Quaterniond(T_a_b.rotation()).conjugate()),
        t_a_b_measured_(T_a_b.translation()),
        sqrt_information_(sqrt_information) {}

  template <typename T>
  bool operator()(const T* q_world_a_data, const T* t_world_a_data, const T* q_world_b_data,
                  const T* t_world_b_data, T* residuals) const {
    using Quaternion = Eigen::Quaternion<T>;
    using Vector3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Quaternion> q_world_a(q_world_a_data);
    const Eigen::Map<const Vector3> t_world_a(t_world_a_data);
    const Eigen::Map<const Quaternion> q_world_b(q_world_b_data);
    const Eigen::Map<const Vector3> t_world_b(t_world_b_data);
    // Estimated T_a_b = T_world_a^-1 T_world_b.
    const Quaternion q_a_world = q_world_a.conjugate();
    const Quaternion q_a_b = q_a_world * q_world_b;
    const Vector3 t_a_b = q_a_world * (t_world_b - t_world_a);
    // Error E = T_a_b_measured^-1 T_a_b.
    const Quaternion q_b_a_measured = q_b_a_measured_.template cast<T>();
    const Quaternion q_error = q_b_a_measured * q_a_b;
    Eigen::Matrix<T, 6, 1> error;
    const T q_error_wxyz[4] = {q_error.w(), q_error.x(), q_error.y(), q_error.z()};
    ceres::QuaternionToAngleAxis(q_error_wxyz, error.data());
    error.template tail<3>() = q_b_a_measured * (t_a_b - t_a_b_measured_.template cast<T>());
    Eigen::Map<Eigen::Matrix<T, 6, 1>> r(residuals);
    r = sqrt_information_.template cast<T>() * error;
    return true;
  }

  static std::unique_ptr<ceres::CostFunction> Create(const PoseGraphEdge& edge) {
    return std::make_unique<ceres::AutoDiffCostFunction<RelativePoseResidual, 6, 4, 3, 4, 3>>(
        new RelativePoseResidual(edge.T_a_b, SqrtOfInformation(edge)));
  }

 private:
  Eigen::Quaterniond q_b_a_measured_;
  Eigen::Vector3d t_a_b_measured_;
  Matrix6d sqrt_information_;
};

// A node's pose as the solver's parameter blocks.
struct NodeState {
  Eigen::Quaterniond q_world_camera;
  Eigen::Vector3d t_world_camera;
};

Eigen::Isometry3d ToIsometry(const NodeState& state) {
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  T_world_camera.linear() = state.q_world_camera.normalized().toRotationMatrix();
  T_world_camera.translation() = state.t_world_camera;
  return T_world_camera;
}

void CheckGraph(const PoseGraph& graph, const PoseGraphOptions& options) {
  if (options.max_iterations < 0 || options.num_threads < 1) {
    throw std::invalid_argument("pose graph: options need max_iterations >= 0, num_threads >= 1");
  }
  bool any_fixed = false;
  for (const auto& [id, node] : graph.nodes) any_fixed = any_fixed || node.fixed;
  if (!any_fixed) {
    throw std::invalid_argument("pose graph: no node is fixed (of " +
                                std::to_string(graph.nodes.size()) + " nodes)");
  }
  for (const PoseGraphEdge& edge : graph.edges) {
    FindPoseGraphNode(graph, edge.id_a);
    FindPoseGraphNode(graph, edge.id_b);
    if (edge.id_a == edge.id_b) {
      throw std::invalid_argument("pose graph: an edge joins keyframe " +
                                  std::to_string(edge.id_a) + " to itself");
    }
  }
}

ceres::Solver::Summary Solve(const PoseGraph& graph, const PoseGraphOptions& options,
                             std::map<int, NodeState>* states) {
  ceres::Problem::Options problem_options;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  ceres::EigenQuaternionManifold quaternion_manifold;
  for (const PoseGraphEdge& edge : graph.edges) {
    NodeState& a = states->at(edge.id_a);
    NodeState& b = states->at(edge.id_b);
    problem.AddResidualBlock(RelativePoseResidual::Create(edge).release(), nullptr,
                             a.q_world_camera.coeffs().data(), a.t_world_camera.data(),
                             b.q_world_camera.coeffs().data(), b.t_world_camera.data());
  }
  for (auto& [id, state] : *states) {
    double* q = state.q_world_camera.coeffs().data();
    if (!problem.HasParameterBlock(q)) continue;  // a node without edges
    problem.SetManifold(q, &quaternion_manifold);
    if (graph.nodes.at(id).fixed) {
      problem.SetParameterBlockConstant(q);
      problem.SetParameterBlockConstant(state.t_world_camera.data());
    }
  }
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver_options.max_num_iterations = options.max_iterations;
  solver_options.num_threads = options.num_threads;
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);
  return summary;
}

}  // namespace

const PoseGraphNode& FindPoseGraphNode(const PoseGraph& graph, int id) {
  const auto it = graph.nodes.find(id);
  if (it == graph.nodes.end()) {
    throw std::invalid_argument("pose graph: keyframe " + std::to_string(id) +
                                " is not a node of the graph");
  }
  return it->second;
}

PoseGraphEdge MakePoseGraphEdge(const PoseGraph& graph, int id_a, int id_b, PoseGraphEdgeKind kind,
                                const PoseGraphInformation& information) {
  PoseGraphEdge edge;
  edge.id_a = id_a;
  edge.id_b = id_b;
  edge.T_a_b = FindPoseGraphNode(graph, id_a).T_world_camera.inverse() *
               FindPoseGraphNode(graph, id_b).T_world_camera;
  edge.information = information;
  edge.kind = kind;
  return edge;
}

PoseGraphInformation PoseGraphEdgeInformation(double sigma_translation_m,
                                              double sigma_rotation_rad) {
  if (!(sigma_translation_m > 0) || !(sigma_rotation_rad > 0)) {
    throw std::invalid_argument("pose graph: edge sigmas must be positive");
  }
  PoseGraphInformation information = PoseGraphInformation::Zero();
  information.diagonal().head<3>().setConstant(1.0 / (sigma_rotation_rad * sigma_rotation_rad));
  information.diagonal().tail<3>().setConstant(1.0 / (sigma_translation_m * sigma_translation_m));
  return information;
}

Eigen::Matrix<double, 6, 1> PoseGraphResidual(const PoseGraphEdge& edge,
                                              const Eigen::Isometry3d& T_world_a,
                                              const Eigen::Isometry3d& T_world_b) {
  const RelativePoseResidual residual(edge.T_a_b, SqrtOfInformation(edge));
  const Eigen::Quaterniond q_world_a(T_world_a.rotation()), q_world_b(T_world_b.rotation());
  const Eigen::Vector3d t_world_a = T_world_a.translation(), t_world_b = T_world_b.translation();
  Eigen::Matrix<double, 6, 1> r;
  residual(q_world_a.coeffs().data(), t_world_a.data(), q_world_b.coeffs().data(), t_world_b.data(),
           r.data());
  return r;
}

PoseGraphResult OptimisePoseGraph(const PoseGraph& graph, const PoseGraphOptions& options) {
  CheckGraph(graph, options);
  std::map<int, NodeState> states;
  for (const auto& [id, node] : graph.nodes) {
    const Eigen::Isometry3d& T = node.T_world_camera;
    states[id] = {Eigen::Quaterniond(T.rotation()), T.translation()};
  }
  const ceres::Solver::Summary summary = Solve(graph, options, &states);
  PoseGraphResult result;
  result.success = summary.IsSolutionUsable();
  result.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
  result.initial_cost = summary.initial_cost;
  result.final_cost = summary.final_cost;
  for (const auto& [id, state] : states) {
    const PoseGraphNode& node = graph.nodes.at(id);
    result.T_world_camera[id] = node.fixed ? node.T_world_camera : ToIsometry(state);
  }
  return result;
}

}  // namespace dslam
