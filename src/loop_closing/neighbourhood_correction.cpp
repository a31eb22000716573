#include "dslam/loop_closing/neighbourhood_correction.h"

#include "dslam/loop_closing/pose_correction.h"

namespace dslam {

std::map<int, Eigen::Isometry3d> CorrectLoopNeighbourhood(
    const PoseGraph& graph, int current_id, const Eigen::Isometry3d& T_world_current_corrected,
    const std::vector<int>& neighbourhood) {
  const Eigen::Isometry3d& T_world_current = FindPoseGraphNode(graph, current_id).T_world_camera;
  std::map<int, Eigen::Isometry3d> corrected;
  corrected[current_id] = T_world_current_corrected;
  for (const int id : neighbourhood) {
    if (id == current_id) continue;
    corrected[id] = CorrectPose(FindPoseGraphNode(graph, id).T_world_camera, T_world_current,
                                T_world_current_corrected);
  }
  return corrected;
}

void SetInitialGuesses(const std::map<int, Eigen::Isometry3d>& T_world_camera, PoseGraph* graph) {
  for (const auto& [id, T] : T_world_camera) FindPoseGraphNode(*graph, id);
  for (const auto& [id, T] : T_world_camera) graph->nodes.at(id).T_world_camera = T;
}

}  // namespace dslam
