// dslam_eval_objects: moving objects estimated by `dslam_run_dataset --objects` against the truth
// of a dslam_synth folder (objects.txt), with the scores of dslam/eval/object_metrics.h.
//   dslam_eval_objects --dataset FOLDER --objects EST.txt [--trajectory EST_TRAJ.txt]
//                      [--json OUT.json] [--gate M] [--max-range M] [--min-share S]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "dslam/eval/json_writer.h"
#include "dslam/eval/object_metrics.h"
#include "dslam/eval/trajectory_metrics.h"
#include "dslam/io/dataset_io.h"
#include "dslam/io/trajectory_io.h"
#include "eval_tool.h"

namespace {

constexpr char kUsage[] =
    "usage: dslam_eval_objects --dataset FOLDER --objects EST.txt [--trajectory EST_TRAJ.txt]\n"
    "                          [--json OUT.json] [--gate M] [--max-range M] [--min-share S]\n"
    "  --dataset     dslam_synth folder: objects.txt, groundtruth.txt, rgb.txt\n"
    "  --objects     estimates 'timestamp id x y z vx vy vz ex ey ez' in the trajectory's frame\n"
    "  --trajectory  the run's trajectory: its first pose places the estimates in the world\n"
    "                (default: the estimates' frame is the first frame's optical frame)\n"
    "  --json        also write the numbers as JSON to this file\n"
    "  --gate        largest centroid distance of a match [m] (default 0.5)\n"
    "  --max-range   truth objects farther from the camera are not evaluated [m] (default 4)\n"
    "  --min-share   truth objects covering less of the image are not evaluated (default 0.02)\n";

std::string Fixed(double value, int decimals) {
  if (std::isnan(value)) return "n/a";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  return buffer;
}

void PrintTable(const dslam::ObjectMetrics& m, const dslam::ObjectMetricsOptions& o) {
  const auto row = [](const std::string& name, const std::string& unit, const std::string& value) {
    std::printf("%-28s %-6s %s\n", name.c_str(), unit.c_str(), value.c_str());
  };
  row("evaluated truth objects", "",
      std::to_string(m.truth_object_frames) + " object-frames (within " + Fixed(o.max_range_m, 1) +
          " m, >= " + Fixed(100.0 * o.min_pixel_share, 1) + " % of the image; " +
          std::to_string(m.frames) + " frames)");
  row("found share", "",
      Fixed(m.found_share, 4) + " (" + std::to_string(m.found) + " of " +
          std::to_string(m.truth_object_frames) + ")");
  row("centroid error median", "[m]", Fixed(m.centroid_error_median_m, 4));
  row("velocity error median", "[m/s]", Fixed(m.velocity_error_median_mps, 4));
  row("false share", "",
      Fixed(m.false_share, 4) + " (" + std::to_string(m.false_objects) + " of " +
          std::to_string(m.estimated_object_frames - m.ignored_estimates) + " scored; " +
          std::to_string(m.ignored_estimates) + " on unevaluated truth objects)");
  row("id switches", "", std::to_string(m.id_switches));
  row("MOTA", "", Fixed(m.mota, 4));
  row("estimates without a frame", "", std::to_string(m.unassociated_estimates));
}

dslam::JsonObject MetricsJson(const dslam::ObjectMetrics& m, const dslam::ObjectMetricsOptions& o,
                              const dslam::tools::Options& values) {
  constexpr int kDigits = 9;
  dslam::JsonObject json;
  json.AddString("dataset", values.at("dataset"))
      .AddString("objects", values.at("objects"))
      .AddNumber("gate_m", o.gate_m, kDigits)
      .AddNumber("max_range_m", o.max_range_m, kDigits)
      .AddNumber("min_pixel_share", o.min_pixel_share, kDigits)
      .AddInteger("frames", m.frames)
      .AddInteger("truth_object_frames", m.truth_object_frames)
      .AddInteger("found", m.found)
      .AddNumber("found_share", m.found_share, kDigits)
      .AddNumber("centroid_error_median_m", m.centroid_error_median_m, kDigits)
      .AddNumber("velocity_error_median_mps", m.velocity_error_median_mps, kDigits)
      .AddInteger("estimated_object_frames", m.estimated_object_frames)
      .AddInteger("ignored_estimates", m.ignored_estimates)
      .AddInteger("false_objects", m.false_objects)
      .AddNumber("false_share", m.false_share, kDigits)
      .AddInteger("id_switches", m.id_switches)
      .AddNumber("mota", m.mota, kDigits)
      .AddInteger("unassociated_estimates", m.unassociated_estimates)
      .AddInteger("unassociated_truth", m.unassociated_truth);
  return json;
}

int Run(const dslam::tools::Options& values) {
  using dslam::tools::NumberKind;
  using dslam::tools::NumberOption;
  dslam::ObjectMetricsOptions options;
  options.gate_m = NumberOption(values, "gate", options.gate_m, NumberKind::kNonNegative);
  options.max_range_m =
      NumberOption(values, "max-range", options.max_range_m, NumberKind::kNonNegative);
  options.min_pixel_share =
      NumberOption(values, "min-share", options.min_pixel_share, NumberKind::kNonNegative);
  const std::string folder = values.at("dataset");
  const dslam::tools::WorldFrame world =
      dslam::tools::EstimateWorldFrame(folder, values, options.max_dt_s);
  const dslam::Trajectory& groundtruth = world.groundtruth;
  const Eigen::Isometry3d& T_world_estworld = world.T_world_estimate;
  const dslam::ObjectMetrics metrics = dslam::EvaluateObjects(
      dslam::ReadTruthObjects(folder + "/objects.txt"),
      dslam::ReadEstimatedObjects(values.at("objects")), groundtruth, T_world_estworld, options);
  PrintTable(metrics, options);
  if (values.count("json")) {
    dslam::WriteJsonFile(values.at("json"), MetricsJson(metrics, options, values));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return dslam::tools::RunTool(
      "dslam_eval_objects", kUsage, argc, argv,
      {"dataset", "objects", "trajectory", "json", "gate", "max-range", "min-share"},
      {"dataset", "objects"}, Run);
}
