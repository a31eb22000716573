// dslam_spd_bench: median runtime of DetermineStaticPoints on point scenes (a room with a
// moving cluster, see dslam/synth/point_scene.h) for a few problem sizes and frame counts.
// Usage: dslam_spd_bench [repetitions=50] [method=least_squares|direct]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "dslam/eval/quantile.h"
#include "dslam/static_points/static_points.h"
#include "dslam/synth/point_scene.h"

namespace {

void Bench(int points, int frames, int repetitions, const dslam::StaticPointsConfig& config) {
  dslam::synth::PointSceneOptions o;
  o.frames = frames;
  o.dynamic_points = points / 6;
  o.static_points = points - o.dynamic_points;
  const dslam::synth::PointScene scene = dslam::synth::MakePointScene(o);
  std::vector<double> total, graph, culling, components;
  dslam::StaticPointsStats last;
  for (int r = 0; r < repetitions; ++r) {
    last = dslam::DetermineStaticPoints(scene.input, config).stats;
    total.push_back(last.total_ms);
    graph.push_back(last.graph_ms);
    culling.push_back(last.culling_ms);
    components.push_back(last.components_ms);
  }
  std::printf("| %5d | %2d | %6d | %5d | %3d | %7.3f | %7.3f | %7.3f | %7.3f |\n", points, frames,
              last.edges, last.culled_edges, last.rounds, dslam::Median(total),
              dslam::Median(graph), dslam::Median(culling), dslam::Median(components));
}

}  // namespace

int main(int argc, char** argv) {
  const int repetitions = argc > 1 ? std::max(1, std::atoi(argv[1])) : 50;
  dslam::StaticPointsConfig config;
  if (argc > 2) config.method = argv[2];
  config.Fields(config, dslam::BoundsChecker("static_points."));
  std::printf("method %s, %d repetitions, median [ms]\n", config.method.c_str(), repetitions);
  std::printf(
      "| points | frames | edges | culled | rounds | total | graph | culling | components |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (int points : {300, 1000}) {
    for (int frames : {2, 8}) Bench(points, frames, repetitions, config);
  }
  return 0;
}
