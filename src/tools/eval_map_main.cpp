// dslam_eval_map: a static map (PCD, e.g. from `dslam_run_dataset --map`) against the truth of a
// dslam_synth folder (depth_true/, mask/, groundtruth.txt), with the scores of
// dslam/eval/map_metrics.h: ghost share, static coverage, static share; and an occupancy grid
// (`dslam_run_dataset --grid`) with dslam/eval/grid_metrics.h: precision, recall, ghost cells.
//   dslam_eval_map --dataset FOLDER [--map MAP.pcd] [--grid GRID.yaml [--unmasked-map U.pcd]]
//                  [--trajectory EST_TRAJ.txt] [--json OUT.json] [--radius M] [--voxel M]
//                  [--pixel-stride N] [--frame-stride N]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "dslam/eval/grid_metrics.h"
#include "dslam/eval/json_writer.h"
#include "dslam/eval/map_metrics.h"
#include "dslam/eval/trajectory_metrics.h"
#include "dslam/io/dataset_io.h"
#include "dslam/io/trajectory_io.h"
#include "dslam/mapping/coloured_cloud.h"
#include "dslam/mapping/occupancy_grid.h"
#include "eval_tool.h"

namespace {

constexpr char kUsage[] =
    "usage: dslam_eval_map --dataset FOLDER [--map MAP.pcd] [--grid GRID.yaml\n"
    "                      [--unmasked-map U.pcd]] [--trajectory EST_TRAJ.txt]\n"
    "                      [--json OUT.json] [--radius M] [--voxel M] [--pixel-stride N]\n"
    "                      [--frame-stride N]\n"
    "  --dataset       dslam_synth folder: depth_true.txt, mask.txt, groundtruth.txt, rgb.txt\n"
    "  --map           PCD with fields x y z (others ignored) in the trajectory's frame\n"
    "  --grid          occupancy grid YAML of dslam_run_dataset --grid (its PGM beside it)\n"
    "  --unmasked-map  with --grid: a map (PCD, e.g. --map-unmasked) whose points in the\n"
    "                  grid's band are scored as occupied cells: the grid without masks and rays\n"
    "  --trajectory    the run's trajectory: its first pose places the map in the world\n"
    "                  (default: the map's frame is the first frame's optical frame)\n"
    "  --json          also write the numbers as JSON to this file\n"
    "  --radius        distance of 'within' and 'farther than' [m] (default 0.05)\n"
    "  --voxel         voxel edge of the reference clouds [m] (default 0.01)\n"
    "  --pixel-stride  every N-th pixel and row of the noise-free depth (default 2)\n"
    "  --frame-stride  every N-th frame (default 1)\n";

/// The map's points moved into the world by T_world_map.
std::vector<Eigen::Vector3d> LoadMap(const std::string& path,
                                     const Eigen::Isometry3d& T_world_map) {
  const dslam::ColouredCloud cloud = dslam::ReadPcd(path);
  std::vector<Eigen::Vector3d> points;
  points.reserve(cloud.size());
  for (const dslam::ColouredPoint& p : cloud) points.push_back(T_world_map * p.p.cast<double>());
  return points;
}

void PrintTable(const dslam::MapMetrics& m, const dslam::MapMetricsOptions& o, int frames) {
  const auto row = [](const std::string& name, const std::string& value) {
    std::printf("%-24s %s\n", name.c_str(), value.c_str());
  };
  const auto share = [](double value, size_t count, size_t of) {
    char buffer[128];
    std::snprintf(buffer, sizeof(buffer), "%.4f (%zu of %zu)", value, count, of);
    return std::string(buffer);
  };
  char radius[64];
  std::snprintf(radius, sizeof(radius), "%.3f m", o.radius_m);
  row("map points", std::to_string(m.map_points));
  row("ghost share", share(m.ghost_share, m.ghost_points, m.map_points));
  row("static coverage",
      share(m.static_coverage, m.covered_static_points, m.static_reference_points));
  row("static share", share(m.static_share, m.near_static_points, m.map_points));
  row("radius", radius);
  row("reference", std::to_string(m.static_reference_points) + " static, " +
                       std::to_string(m.dynamic_reference_points) + " moving-object voxels of " +
                       std::to_string(frames) + " frames");
}

dslam::JsonObject MetricsJson(const dslam::MapMetrics& m, const dslam::MapMetricsOptions& o,
                              int frames, const dslam::tools::Options& values) {
  constexpr int kDigits = 9;
  dslam::JsonObject json;
  json.AddString("dataset", values.at("dataset"))
      .AddString("map", values.at("map"))
      .AddNumber("radius_m", o.radius_m, kDigits)
      .AddNumber("voxel_m", o.voxel_m, kDigits)
      .AddInteger("pixel_stride", o.pixel_stride)
      .AddInteger("frame_stride", o.frame_stride)
      .AddInteger("reference_frames", frames)
      .AddInteger("map_points", static_cast<long long>(m.map_points))
      .AddInteger("ghost_points", static_cast<long long>(m.ghost_points))
      .AddNumber("ghost_share", m.ghost_share, kDigits)
      .AddInteger("static_reference_points", static_cast<long long>(m.static_reference_points))
      .AddInteger("dynamic_reference_points", static_cast<long long>(m.dynamic_reference_points))
      .AddInteger("covered_static_points", static_cast<long long>(m.covered_static_points))
      .AddNumber("static_coverage", m.static_coverage, kDigits)
      .AddInteger("near_static_points", static_cast<long long>(m.near_static_points))
      .AddNumber("static_share", m.static_share, kDigits);
  return json;
}

void PrintGrid(const char* name, const dslam::GridMetrics& m) {
  std::printf("%-24s %zu occupied, precision %.4f, recall %.4f (%zu static cells)\n", name,
              m.occupied_cells, m.precision, m.recall, m.static_truth_cells);
  std::printf("%-24s %zu (of %zu cells where only people stood)\n",
              (std::string(name) + " ghost cells:").c_str(), m.ghost_cells, m.people_truth_cells);
}

void AddGrid(const std::string& prefix, const dslam::GridMetrics& m, dslam::JsonObject* json) {
  constexpr int kDigits = 9;
  json->AddInteger(prefix + "occupied_cells", static_cast<long long>(m.occupied_cells))
      .AddInteger(prefix + "static_truth_cells", static_cast<long long>(m.static_truth_cells))
      .AddInteger(prefix + "people_truth_cells", static_cast<long long>(m.people_truth_cells))
      .AddInteger(prefix + "ghost_cells", static_cast<long long>(m.ghost_cells))
      .AddNumber(prefix + "precision", m.precision, kDigits)
      .AddNumber(prefix + "recall", m.recall, kDigits);
}

// --grid (and --unmasked-map): printed as `grid ...` and `ghost cells: N` lines and added to the
// JSON as grid_* (unmasked_grid_*).
void EvaluateGridFile(const dslam::tools::Options& values, const Eigen::Isometry3d& T_world_map,
                      const dslam::MapReference& reference, dslam::JsonObject* json) {
  const dslam::OccupancyGrid grid = dslam::ReadMapServerFiles(values.at("grid"));
  const dslam::GridMetrics metrics = dslam::EvaluateGrid(grid, T_world_map, reference);
  PrintGrid("grid", metrics);
  json->AddString("grid", values.at("grid"));
  AddGrid("grid_", metrics, json);
  if (!values.count("unmasked-map")) return;
  const std::vector<Eigen::Vector3d> points = LoadMap(values.at("unmasked-map"), T_world_map);
  const dslam::GridMetrics unmasked =
      dslam::EvaluateOccupiedPoints(grid, T_world_map, points, reference);
  PrintGrid("unmasked", unmasked);
  AddGrid("unmasked_grid_", unmasked, json);
}

int Run(const dslam::tools::Options& values) {
  using dslam::tools::NumberKind;
  using dslam::tools::NumberOption;
  dslam::MapMetricsOptions options;
  options.radius_m = NumberOption(values, "radius", options.radius_m, NumberKind::kPositive);
  options.voxel_m = NumberOption(values, "voxel", options.voxel_m, NumberKind::kPositive);
  options.pixel_stride = static_cast<int>(
      NumberOption(values, "pixel-stride", options.pixel_stride, NumberKind::kPositiveWhole));
  options.frame_stride = static_cast<int>(
      NumberOption(values, "frame-stride", options.frame_stride, NumberKind::kPositiveWhole));
  const std::string folder = values.at("dataset");
  if (!values.count("map") && !values.count("grid")) {
    throw dslam::tools::UsageError("give --map, --grid or both");
  }
  if (values.count("unmasked-map") && !values.count("grid")) {
    throw dslam::tools::UsageError("--unmasked-map needs --grid");
  }
  constexpr double kMaxDt_s = 0.005;
  const Eigen::Isometry3d T_world_map =
      dslam::tools::EstimateWorldFrame(folder, values, kMaxDt_s).T_world_estimate;
  const dslam::MapReference reference = dslam::LoadMapReference(folder, options);
  dslam::JsonObject json;
  if (values.count("map")) {
    const std::vector<Eigen::Vector3d> map = LoadMap(values.at("map"), T_world_map);
    const dslam::MapMetrics metrics = dslam::EvaluateMap(map, reference, options.radius_m);
    PrintTable(metrics, options, reference.frames);
    json = MetricsJson(metrics, options, reference.frames, values);
  } else {
    json.AddString("dataset", folder).AddInteger("reference_frames", reference.frames);
  }
  if (values.count("grid")) EvaluateGridFile(values, T_world_map, reference, &json);
  if (values.count("json")) dslam::WriteJsonFile(values.at("json"), json);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return dslam::tools::RunTool("dslam_eval_map", kUsage, argc, argv,
                               {"dataset", "map", "grid", "unmasked-map", "trajectory", "json",
                                "radius", "voxel", "pixel-stride", "frame-stride"},
                               {"dataset"}, Run);
}
