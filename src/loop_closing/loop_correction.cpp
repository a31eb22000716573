#include "dslam/loop_closing/loop_correction.h"

#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "dslam/loop_closing/covisibility.h"

namespace dslam {
namespace {

// The spanning tree (each keyframe to the one made before it; kWeakEdgeSigmaScale times the
// sigmas when the motion from it rests on a weak episode, KeyFrame::weak_since_previous) and
// covisibility edges, measured from the current poses.
void AddOdometryEdges(const Map& map, const std::vector<const KeyFrame*>& keyframes,
                      PoseGraph* graph) {
  std::set<std::pair<int, int>> spanning;
  for (size_t k = 1; k < keyframes.size(); ++k) {
    spanning.emplace(keyframes[k - 1]->id, keyframes[k]->id);
    const double scale = keyframes[k]->weak_since_previous ? kWeakEdgeSigmaScale : 1.0;
    graph->edges.push_back(MakePoseGraphEdge(
        *graph, keyframes[k - 1]->id, keyframes[k]->id, PoseGraphEdgeKind::kSpanningTree,
        PoseGraphEdgeInformation(scale * kOdometryEdgeSigmaM, scale * kOdometryEdgeSigmaRad)));
  }
  const PoseGraphInformation covisible =
      PoseGraphEdgeInformation(kOdometryEdgeSigmaM, kOdometryEdgeSigmaRad);
  const CovisibilityIndex index(map);
  for (const KeyFrame* keyframe : keyframes) {
    for (const auto& [other, shared] : index.Covisible(*keyframe)) {
      const std::pair<int, int> pair(keyframe->id, other);  // each pair once: older id first
      if (other < keyframe->id || shared < kCovisibilityEdgePoints || spanning.count(pair) > 0) {
        continue;
      }
      graph->edges.push_back(MakePoseGraphEdge(*graph, pair.first, pair.second,
                                               PoseGraphEdgeKind::kCovisibility, covisible));
    }
  }
}

}  // namespace

PoseGraph BuildLoopPoseGraph(const Map& map, const std::vector<LoopEdge>& loops) {
  const std::vector<const KeyFrame*> keyframes = map.AllKeyFrames();
  PoseGraph graph;
  for (const KeyFrame* keyframe : keyframes) {
    graph.nodes[keyframe->id] = PoseGraphNode{keyframe->T_world_camera, false};
  }
  if (loops.empty()) throw std::invalid_argument("BuildLoopPoseGraph: no loop");
  for (int id : {loops.back().match_keyframe_id, loops.back().query_keyframe_id}) {
    if (graph.nodes.count(id) == 0) {
      throw std::invalid_argument("BuildLoopPoseGraph: keyframe " + std::to_string(id) +
                                  " is not in the map");
    }
  }
  graph.nodes.begin()->second.fixed = true;  // the oldest keyframe
  AddOdometryEdges(map, keyframes, &graph);
  for (const LoopEdge& loop : loops) {
    if (graph.nodes.count(loop.match_keyframe_id) == 0 ||
        graph.nodes.count(loop.query_keyframe_id) == 0) {
      continue;  // a keyframe of an older loop was erased
    }
    PoseGraphEdge edge;
    edge.id_a = loop.match_keyframe_id;
    edge.id_b = loop.query_keyframe_id;
    edge.T_a_b = loop.T_match_query;
    edge.information = PoseGraphEdgeInformation(kLoopEdgeSigmaM, kLoopEdgeSigmaRad);
    edge.kind = PoseGraphEdgeKind::kLoop;
    graph.edges.push_back(edge);
  }
  return graph;
}

std::map<int, Eigen::Isometry3d> CorrectedKeyFramePoses(const PoseGraph& graph,
                                                        const PoseGraphOptions& options) {
  const PoseGraphResult result = OptimisePoseGraph(graph, options);
  if (!result.success) return {};
  return result.T_world_camera;
}

}  // namespace dslam
