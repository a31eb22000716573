#include "dslam/static_points/static_points.h"

#include <algorithm>
#include <utility>

#include "dslam/core/stopwatch.h"

namespace dslam {
namespace {

CullingResult RunCulling(const CorrelationInput& input, const std::vector<GraphEdge>& edges,
                         const StaticPointsConfig& config) {
  if (config.method == "direct") {
    CullingResult result = DirectEdgeTest(input, edges, config.direct_probability);
    result.points_world = input.points_world;
    return result;
  }
  CullingOptions options;
  options.chi2_threshold = config.chi2_threshold;
  options.min_inlier_fraction = config.min_inlier_fraction;
  return CullInconsistentEdges(input, edges, options);
}

void CountLabels(StaticPointsResult* result) {
  StaticPointsStats& s = result->stats;
  for (PointLabel label : result->labels) {
    s.static_points += label == PointLabel::kStatic;
    s.dynamic_points += label == PointLabel::kDynamic;
    s.isolated_points += label == PointLabel::kIsolated;
  }
  s.components = ComponentCount(result->component);
  s.culled_edges =
      static_cast<int>(std::count(result->edge_kept.begin(), result->edge_kept.end(), false));
}

}  // namespace

void RequireEvidenceAgainstStatic(const std::vector<GraphEdge>& edges,
                                  const std::vector<bool>& edge_verified,
                                  const std::vector<int>& component, int static_component,
                                  std::vector<PointLabel>* labels) {
  if (static_component < 0) return;
  const int num_components = ComponentCount(component);
  std::vector<bool> evidence(num_components, false);
  for (size_t e = 0; e < edges.size(); ++e) {
    if (!edge_verified[e]) continue;
    const int ci = component[edges[e].i], cj = component[edges[e].j];
    if (ci == static_component && cj != static_component) evidence[cj] = true;
    if (cj == static_component && ci != static_component) evidence[ci] = true;
  }
  for (size_t i = 0; i < labels->size(); ++i) {
    const PointLabel label = (*labels)[i];
    if ((label == PointLabel::kDynamic || label == PointLabel::kIsolated) &&
        !evidence[component[i]]) {
      (*labels)[i] = PointLabel::kUnverified;
    }
  }
}

StaticPointsResult DetermineStaticPoints(const CorrelationInput& input,
                                         const StaticPointsConfig& config) {
  const Stopwatch graph;
  std::vector<GraphEdge> edges = BuildDelaunayGraph(input.points_world);
  return DetermineStaticPoints(input, std::move(edges), graph.ElapsedMs(), config);
}

StaticPointsResult DetermineStaticPoints(const CorrelationInput& input,
                                         std::vector<GraphEdge> edges, double graph_ms,
                                         const StaticPointsConfig& config) {
  StaticPointsResult result;
  const Stopwatch total;
  Stopwatch stage;
  result.edges = std::move(edges);
  result.stats.graph_ms = graph_ms;

  CullingResult culling = RunCulling(input, result.edges, config);
  result.edge_kept = std::move(culling.edge_kept);
  result.points_world = std::move(culling.points_world);
  result.stats.culling_ms = stage.Restart();

  const int num_points = static_cast<int>(input.points_world.size());
  // Only edges that were tested (measured in enough frames) and passed connect points: an
  // untested edge between a new point on a walking person and the wall behind it would otherwise
  // glue the person to the static world.
  std::vector<bool> connects(result.edges.size());
  std::vector<bool> has_verified_edge(num_points, false);
  result.edge_verified.resize(result.edges.size());
  for (size_t e = 0; e < result.edges.size(); ++e) {
    result.edge_verified[e] = culling.edge_measurements[e] >= config.min_edge_measurements;
    connects[e] = result.edge_kept[e] && result.edge_verified[e];
    if (result.edge_verified[e]) {
      has_verified_edge[result.edges[e].i] = has_verified_edge[result.edges[e].j] = true;
    }
  }
  result.component = ConnectedComponents(num_points, result.edges, connects);
  StaticSelectionOptions selection_options;
  selection_options.min_static_points = config.min_static_points;
  StaticSelection selection =
      SelectStaticComponent(result.points_world, result.component, selection_options);
  result.labels = std::move(selection.labels);
  RequireEvidenceAgainstStatic(result.edges, result.edge_verified, result.component,
                               selection.static_component, &result.labels);
  if (selection.static_component >= 0) {  // otherwise every label stays kUndecided
    for (int i = 0; i < num_points; ++i) {
      if (!has_verified_edge[i]) result.labels[i] = PointLabel::kUnverified;
    }
  }
  result.static_component = selection.static_component;
  result.stats.components_ms = stage.Restart();
  result.stats.total_ms = graph_ms + total.ElapsedMs();

  result.stats.points = num_points;
  result.stats.edges = static_cast<int>(result.edges.size());
  result.stats.measurements = culling.measurements;
  result.stats.rounds = culling.rounds;
  CountLabels(&result);
  return result;
}

}  // namespace dslam
