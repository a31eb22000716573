// dslam_eval_map: a static map (PCD, e.g. from `dslam_run_dataset --map`) against the truth of a
// dslam_synth folder (depth_true/, mask/, groundtruth.txt), with the scores of
// dslam/eval/map_metrics.h: ghost share, static coverage, static share.
//   dslam_eval_map --dataset FOLDER --map MAP.pcd [--trajectory EST_TRAJ.txt] [--json OUT.json]
//                  [--radius M] [--voxel M] [--pixel-stride N] [--frame-stride N]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "dslam/eval/json_writer.h"
#include "dslam/eval/map_metrics.h"
#include "dslam/eval/trajectory_metrics.h"
#include "dslam/io/dataset_io.h"
#include "dslam/io/trajectory_io.h"
#include "dslam/mapping/coloured_cloud.h"
#include "eval_tool.h"

namespace {

constexpr char kUsage[] =
    "usage: dslam_eval_map --dataset FOLDER --map MAP.pcd [--trajectory EST_TRAJ.txt]\n"
    "                      [--json OUT.json] [--radius M] [--voxel M] [--pixel-stride N]\n"
    "                      [--frame-stride N]\n"
    "  --dataset       dslam_synth folder: depth_true.txt, mask.txt, groundtruth.txt, rgb.txt\n"
    "  --map           PCD with fields x y z (others ignored) in the trajectory's frame\n"
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
  constexpr double kMaxDt_s = 0.005;
  const Eigen::Isometry3d T_world_map =
      dslam::tools::EstimateWorldFrame(folder, values, kMaxDt_s).T_world_estimate;
  const std::vector<Eigen::Vector3d> map = LoadMap(values.at("map"), T_world_map);
  const dslam::MapReference reference = dslam::LoadMapReference(folder, options);
  const dslam::MapMetrics metrics = dslam::EvaluateMap(map, reference, options.radius_m);
  PrintTable(metrics, options, reference.frames);
  if (values.count("json")) {
    dslam::WriteJsonFile(values.at("json"),
                         MetricsJson(metrics, options, reference.frames, values));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return dslam::tools::RunTool(
      "dslam_eval_map", kUsage, argc, argv,
      {"dataset", "map", "trajectory", "json", "radius", "voxel", "pixel-stride", "frame-stride"},
      {"dataset", "map"}, Run);
}
