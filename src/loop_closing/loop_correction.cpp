#include "dslam/loop_closing/loop_correction.h"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace dslam {
namespace {

std::vector<const KeyFrame*> AllKeyFrames(const Map& map) {
  std::vector<const KeyFrame*> out;
  for (const auto& entry : map.archived_keyframes()) out.push_back(&entry.second);
  for (const KeyFrame& keyframe : map.keyframes()) out.push_back(&keyframe);
  std::sort(out.begin(), out.end(),
            [](const KeyFrame* a, const KeyFrame* b) { return a->id < b->id; });
  return out;
}

// Pairs (older id, newer id) of keyframes with the number of map points both list.
std::map<std::pair<int, int>, int> SharedPoints(const std::vector<const KeyFrame*>& keyframes) {
  std::unordered_map<PointId, std::vector<int>> observers;
  for (const KeyFrame* keyframe : keyframes) {
    for (PointId id : keyframe->points) observers[id].push_back(keyframe->id);
  }
  std::map<std::pair<int, int>, int> shared;
  for (const auto& entry : observers) {
    const std::vector<int>& ids = entry.second;
    for (size_t a = 0; a < ids.size(); ++a) {
      for (size_t b = a + 1; b < ids.size(); ++b) {
        ++shared[std::minmax(ids[a], ids[b])];
      }
    }
  }
  return shared;
}

}  // namespace

PoseGraph BuildLoopPoseGraph(const Map& map, int match_keyframe_id, int query_keyframe_id,
                             const Eigen::Isometry3d& T_match_query) {
  const std::vector<const KeyFrame*> keyframes = AllKeyFrames(map);
  PoseGraph graph;
  for (const KeyFrame* keyframe : keyframes) {
    graph.nodes[keyframe->id] = PoseGraphNode{keyframe->T_world_camera, false};
  }
  for (int id : {match_keyframe_id, query_keyframe_id}) {
    if (graph.nodes.count(id) == 0) {
      throw std::invalid_argument("BuildLoopPoseGraph: keyframe " + std::to_string(id) +
                                  " is not in the map");
    }
  }
  graph.nodes.begin()->second.fixed = true;  // the oldest keyframe
  const PoseGraphInformation odometry =
      PoseGraphEdgeInformation(kOdometryEdgeSigmaM, kOdometryEdgeSigmaRad);
  std::set<std::pair<int, int>> spanning;
  for (size_t k = 1; k < keyframes.size(); ++k) {
    spanning.emplace(keyframes[k - 1]->id, keyframes[k]->id);
    graph.edges.push_back(MakePoseGraphEdge(graph, keyframes[k - 1]->id, keyframes[k]->id,
                                            PoseGraphEdgeKind::kSpanningTree, odometry));
  }
  for (const auto& [pair, count] : SharedPoints(keyframes)) {
    if (count < kCovisibilityEdgePoints || spanning.count(pair) > 0) continue;
    graph.edges.push_back(MakePoseGraphEdge(graph, pair.first, pair.second,
                                            PoseGraphEdgeKind::kCovisibility, odometry));
  }
  PoseGraphEdge loop;
  loop.id_a = match_keyframe_id;
  loop.id_b = query_keyframe_id;
  loop.T_a_b = T_match_query;
  loop.information = PoseGraphEdgeInformation(kLoopEdgeSigmaM, kLoopEdgeSigmaRad);
  loop.kind = PoseGraphEdgeKind::kLoop;
  graph.edges.push_back(loop);
  return graph;
}

std::map<int, Eigen::Isometry3d> CorrectedKeyFramePoses(const PoseGraph& graph,
                                                        const PoseGraphOptions& options) {
  const PoseGraphResult result = OptimisePoseGraph(graph, options);
  if (!result.success) return {};
  return result.T_world_camera;
}

}  // namespace dslam
