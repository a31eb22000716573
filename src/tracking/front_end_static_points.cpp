#include "dslam/tracking/front_end_static_points.h"

#include <algorithm>
#include <utility>

#include "dslam/core/stopwatch.h"
#include "dslam/static_points/graph_subset.h"
#include "dslam/static_points/point_graph.h"

namespace dslam {
namespace {

void AddObservation(int point, int frame, const Eigen::Vector3d& y, const Eigen::Matrix3d& C,
                    CorrelationInput* input) {
  PointObservation obs;
  obs.point = point;
  obs.frame = frame;
  obs.y_camera = y;
  obs.covariance = C;
  input->observations.push_back(obs);
}

// The correlation problem over the matches `graph_match` with map points at `points_world`
// (parallel): frame 0 is the current frame, frame k + 1 reference_frames[k].
CorrelationInput BuildInput(const std::vector<PointMatch>& matches, const FrameFeatures& features,
                            const Eigen::Isometry3d& T_camera_world,
                            const std::vector<const FrameMeasurements*>& reference_frames,
                            const std::vector<int>& graph_match,
                            std::vector<Eigen::Vector3d> points_world) {
  CorrelationInput input;
  input.T_camera_world.push_back(T_camera_world);
  for (const FrameMeasurements* frame : reference_frames) {
    input.T_camera_world.push_back(frame->T_camera_world);
  }
  input.points_world = std::move(points_world);
  for (size_t index = 0; index < graph_match.size(); ++index) {
    const PointMatch& match = matches[graph_match[index]];
    const PointMeasurement& measurement = *features.features[match.feature].measurement;
    const int point = static_cast<int>(index);
    AddObservation(point, 0, measurement.y_camera, measurement.covariance, &input);
    for (size_t k = 0; k < reference_frames.size(); ++k) {
      const auto found = reference_frames[k]->by_point.find(match.id);
      if (found == reference_frames[k]->by_point.end()) continue;
      AddObservation(point, static_cast<int>(k) + 1, found->second.y_camera,
                     found->second.covariance, &input);
    }
  }
  return input;
}

// Indices into `usable` of the graph's points: all of them up to max_points (or with
// max_points <= 0: no cap); else every unsettled point (unmarked, or a candidate not yet
// verified: where motion is still being decided), thinned evenly over the image only if they
// alone exceed max_points, and verified static points spread evenly over the image for the rest.
std::vector<int> GraphSubset(const Map& map, const std::vector<PointMatch>& matches,
                             const FrameFeatures& features, const std::vector<int>& usable,
                             int max_points) {
  std::vector<int> all(usable.size());
  for (size_t u = 0; u < usable.size(); ++u) all[u] = static_cast<int>(u);
  if (max_points <= 0 || static_cast<int>(usable.size()) <= max_points) return all;
  std::vector<int> groups[2];  // 0: unsettled, 1: verified static
  std::vector<Eigen::Vector2d> uv[2];
  for (size_t u = 0; u < usable.size(); ++u) {
    const PointMatch& match = matches[usable[u]];
    const int group = map.Find(match.id)->IsVerifiedStatic() ? 1 : 0;
    groups[group].push_back(static_cast<int>(u));
    uv[group].push_back(features.features[match.feature].uv_ideal);
  }
  std::vector<int> chosen;
  for (int group = 0; group < 2; ++group) {
    const int room = max_points - static_cast<int>(chosen.size());
    for (int k : SpatiallyEvenSubset(uv[group], room)) chosen.push_back(groups[group][k]);
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

// Appends the usable matches left out of the graph (usable minus chosen, both increasing) to
// out->graph_match with the label of their nearest graph point.
void LabelLeftOutPoints(const Map& map, const std::vector<PointMatch>& matches,
                        const std::vector<int>& usable, const std::vector<int>& chosen,
                        FrontEndStaticPoints* out) {
  if (chosen.size() == usable.size()) return;
  std::vector<int> left_out;
  std::vector<Eigen::Vector3d> left_out_world;
  for (size_t u = 0, c = 0; u < usable.size(); ++u) {
    if (c < chosen.size() && chosen[c] == static_cast<int>(u)) {
      ++c;
      continue;
    }
    left_out.push_back(usable[u]);
    left_out_world.push_back(map.Find(matches[usable[u]].id)->p_world);
  }
  StaticPointsResult& result = out->result;
  const std::vector<int> nearest = NearestGraphPoints(result.points_world, left_out_world);
  for (size_t k = 0; k < left_out.size(); ++k) {
    out->graph_match.push_back(left_out[k]);
    result.labels.push_back(InheritedLabel(result.labels[nearest[k]]));
    result.component.push_back(result.component[nearest[k]]);
    result.points_world.push_back(left_out_world[k]);
  }
}

// Applies `label` of frame `frame_index` to `point`'s marks (ApplyStaticLabels).
void ApplyLabel(PointLabel label, const LabelRules& rules, int frame_index, MapPoint* point) {
  switch (label) {
    case PointLabel::kStatic:
      point->isolated_frames = 0;
      // Consistent with the static world again (e.g. wrongly unmarked, or stopped moving).
      point->LookedStatic(rules.remark_frames);
      if (point->marked && frame_index - point->created_frame >= rules.verify_frames) {
        point->candidate = false;
      }
      break;
    case PointLabel::kDynamic:
      point->Unmark(0);
      break;
    case PointLabel::kIsolated:
      point->static_streak = 0;
      if (++point->isolated_frames >= rules.isolated_frames_to_unmark) point->marked = false;
      break;
    case PointLabel::kUndecided:
    case PointLabel::kUnverified:
      break;
  }
}

}  // namespace

FrontEndGraph BuildFrontEndGraph(const Map& map, const std::vector<PointMatch>& matches,
                                 const FrameFeatures& features, const StaticPointsConfig& config) {
  const Stopwatch watch;
  FrontEndGraph graph;
  for (size_t m = 0; m < matches.size(); ++m) {
    if (map.Find(matches[m].id) != nullptr && features.features[matches[m].feature].measurement) {
      graph.usable.push_back(static_cast<int>(m));
    }
  }
  if (static_cast<int>(graph.usable.size()) < kMinGraphPoints) return graph;
  graph.chosen = GraphSubset(map, matches, features, graph.usable, config.max_graph_points);
  for (int c : graph.chosen) {
    graph.points_world.push_back(map.Find(matches[graph.usable[c]].id)->p_world);
  }
  graph.edges = BuildDelaunayGraph(graph.points_world);
  graph.graph_ms = watch.ElapsedMs();
  return graph;
}

FrontEndStaticPoints DetermineStaticPointsFrontEnd(
    const Map& map, const std::vector<PointMatch>& matches, const FrameFeatures& features,
    const Eigen::Isometry3d& T_camera_world,
    const std::vector<const FrameMeasurements*>& reference_frames,
    const StaticPointsConfig& config) {
  return DetermineStaticPointsFrontEnd(map, matches, features, T_camera_world, reference_frames,
                                       config, BuildFrontEndGraph(map, matches, features, config));
}

FrontEndStaticPoints DetermineStaticPointsFrontEnd(
    const Map& map, const std::vector<PointMatch>& matches, const FrameFeatures& features,
    const Eigen::Isometry3d& T_camera_world,
    const std::vector<const FrameMeasurements*>& reference_frames, const StaticPointsConfig& config,
    FrontEndGraph graph) {
  FrontEndStaticPoints out;
  if (static_cast<int>(graph.usable.size()) < kMinGraphPoints) return out;
  for (int c : graph.chosen) out.graph_match.push_back(graph.usable[c]);
  const CorrelationInput input = BuildInput(matches, features, T_camera_world, reference_frames,
                                            out.graph_match, std::move(graph.points_world));
  out.result = DetermineStaticPoints(input, std::move(graph.edges), graph.graph_ms, config);
  out.ran = true;
  LabelLeftOutPoints(map, matches, graph.usable, graph.chosen, &out);
  return out;
}

std::vector<bool> ApplyStaticLabels(const FrontEndStaticPoints& front_end,
                                    const std::vector<PointMatch>& matches, const LabelRules& rules,
                                    int frame_index, Map* map) {
  std::vector<bool> excluded(matches.size(), false);
  if (!front_end.ran || front_end.result.static_component < 0) return excluded;
  for (size_t g = 0; g < front_end.graph_match.size(); ++g) {
    const int m = front_end.graph_match[g];
    MapPoint* point = map->Find(matches[m].id);
    if (point == nullptr) continue;
    const PointLabel label = front_end.result.labels[g];
    excluded[m] = label == PointLabel::kDynamic || label == PointLabel::kIsolated;
    // A frozen point (Map::Freeze) keeps its marks: its label only excludes it from this frame.
    if (!map->IsFrozenPoint(matches[m].id)) ApplyLabel(label, rules, frame_index, point);
  }
  return excluded;
}

}  // namespace dslam
