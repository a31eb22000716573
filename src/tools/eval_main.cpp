// dslam_eval: trajectory accuracy of an estimate against ground truth (TUM definitions: ATE after
// SE(3) alignment, RPE over 1 s, plus coverage of the sequence). See docs/readme/eval.md.
//   dslam_eval --groundtruth GT --trajectory EST [--camera camera.yaml] [--frames rgb.txt]
//              [--json OUT.json] [--write-groundtruth OUT.txt] [--save-aligned OUT.txt]
//              [--save-groundtruth OUT.txt] [--max-dt S] [--rpe-interval S] [--max-gap S]
//              [--loops LOOPS.txt]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "dslam/eval/groundtruth_correction.h"
#include "dslam/eval/json_writer.h"
#include "dslam/eval/loop_check.h"
#include "dslam/eval/trajectory_metrics.h"
#include "dslam/io/dataset_io.h"
#include "dslam/io/trajectory_io.h"

namespace {

constexpr char kUsage[] =
    "usage: dslam_eval --groundtruth GT.txt --trajectory EST.txt [--camera camera.yaml]\n"
    "                  [--frames rgb.txt] [--json OUT.json] [--write-groundtruth OUT.txt]\n"
    "                  [--save-aligned OUT.txt] [--save-groundtruth OUT.txt]\n"
    "                  [--max-dt S] [--rpe-interval S] [--max-gap S] [--loops LOOPS.txt]\n"
    "  --groundtruth   ground truth, TUM format (timestamp tx ty tz qx qy qz qw)\n"
    "  --trajectory    estimated trajectory T_world_camera, TUM format\n"
    "  --camera        camera.yaml; 'groundtruth_correction: bonn' converts the Bonn marker\n"
    "                  poses of GT to colour-camera poses before evaluation\n"
    "  --frames        rgb.txt of the input frames: coverage is measured over their time span\n"
    "                  (clipped to the ground truth's), else over the ground truth's span\n"
    "  --json          also write the numbers as JSON to this file\n"
    "  --write-groundtruth  write the (corrected) ground truth used, every pose, TUM format\n"
    "  --save-aligned  write the associated estimated poses (estimated stamps) moved into the\n"
    "                  ground truth's world frame by the SE(3) alignment of the ATE, TUM format\n"
    "  --save-groundtruth  write the (corrected) ground-truth poses of the same associated pairs\n"
    "                  (ground-truth stamps), TUM format; line k pairs with line k of\n"
    "                  --save-aligned\n"
    "  --max-dt        association tolerance [s] (default 0.02)\n"
    "  --rpe-interval  RPE interval [s] (default 1.0)\n"
    "  --max-gap       longest gap between estimates counted as covered [s] (default 0.1)\n"
    "  --loops         accepted loops of dslam_run_dataset --loops: each relative pose is checked\n"
    "                  against the ground truth; false when off by more than 0.10 m or 3 deg\n";

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Arguments {
  std::map<std::string, std::string> values;  // option name without "--" -> value
  bool help = false;
};

Arguments ParseArguments(int argc, char** argv) {
  static const std::vector<std::string> kKnown = {
      "groundtruth",  "trajectory",       "camera", "frames",       "json",    "write-groundtruth",
      "save-aligned", "save-groundtruth", "max-dt", "rpe-interval", "max-gap", "loops"};
  Arguments args;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      args.help = true;
      continue;
    }
    const std::string name = arg.rfind("--", 0) == 0 ? arg.substr(2) : "";
    if (std::find(kKnown.begin(), kKnown.end(), name) == kKnown.end()) {
      throw UsageError("unknown argument '" + arg + "'");
    }
    if (i + 1 >= argc) throw UsageError("missing value after " + arg);
    args.values[name] = argv[++i];
  }
  if (args.help) return args;
  for (const char* required : {"groundtruth", "trajectory"}) {
    if (!args.values.count(required))
      throw UsageError(std::string("--") + required + " is required");
  }
  return args;
}

double PositiveNumber(const Arguments& args, const std::string& name, double fallback) {
  const auto it = args.values.find(name);
  if (it == args.values.end()) return fallback;
  size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(it->second, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != it->second.size() || !(value > 0.0) || !std::isfinite(value)) {
    throw UsageError("--" + name + " needs a positive number, got '" + it->second + "'");
  }
  return value;
}

std::string Fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  return buffer;
}

void PrintTable(const dslam::TrajectoryMetrics& m, const std::string& correction) {
  const auto row = [](const std::string& name, const std::string& unit, const std::string& value) {
    std::printf("%-24s %-7s %s\n", name.c_str(), unit.c_str(), value.c_str());
  };
  const bool has_rpe = m.rpe.num_pairs > 0;
  row("ATE RMSE", "[m]", Fixed(m.ate_m.rmse, 6));
  row("ATE mean", "[m]", Fixed(m.ate_m.mean, 6));
  row("ATE median", "[m]", Fixed(m.ate_m.median, 6));
  row("ATE max", "[m]", Fixed(m.ate_m.max, 6));
  row("RPE trans RMSE", "[m/s]", has_rpe ? Fixed(m.rpe.translation_rmse_m_per_s, 6) : "n/a");
  row("RPE rot RMSE", "[deg/s]", has_rpe ? Fixed(m.rpe.rotation_rmse_deg_per_s, 6) : "n/a");
  row("RPE pairs", "", std::to_string(m.rpe.num_pairs));
  const dslam::FrameSteps& steps = m.steps;
  row("step median / max", "[m]",
      Fixed(steps.step_m.median, 4) + " / " + Fixed(steps.step_m.max, 4) + " (truth " +
          Fixed(steps.truth_step_m.median, 4) + " / " + Fixed(steps.truth_step_m.max, 4) + ")");
  row("associated / estimated", "",
      std::to_string(m.num_associated) + " / " + std::to_string(m.num_estimated));
  const dslam::Coverage& c = m.coverage;
  row("coverage", "",
      Fixed(c.fraction, 4) + " (" + Fixed(c.covered_s, 3) + " s of " +
          Fixed(c.span_end_s - c.span_start_s, 3) + " s)");
  row("groundtruth correction", "", correction);
}

// The evaluation's settings and numbers, JSON (scripts/benchmark.py and plot_trajectory read it).
dslam::JsonObject MetricsJson(const dslam::TrajectoryMetrics& m, const Arguments& args,
                              const std::string& correction,
                              const dslam::TrajectoryMetricsOptions& options) {
  constexpr int kDigits = 9;  // significant digits of every number
  const bool has_rpe = m.rpe.num_pairs > 0;
  const double nan = std::nan("");  // written as null
  const dslam::Coverage& c = m.coverage;
  dslam::JsonObject json;
  json.AddString("groundtruth", args.values.at("groundtruth"))
      .AddString("trajectory", args.values.at("trajectory"))
      .AddString("groundtruth_correction", correction)
      .AddNumber("max_association_dt_s", options.max_association_dt_s, kDigits)
      .AddNumber("rpe_interval_s", options.rpe_interval_s, kDigits)
      .AddNumber("max_gap_s", options.max_gap_s, kDigits)
      .AddNumber("ate_rmse_m", m.ate_m.rmse, kDigits)
      .AddNumber("ate_mean_m", m.ate_m.mean, kDigits)
      .AddNumber("ate_median_m", m.ate_m.median, kDigits)
      .AddNumber("ate_max_m", m.ate_m.max, kDigits)
      .AddNumber("rpe_trans_rmse_m_per_s", has_rpe ? m.rpe.translation_rmse_m_per_s : nan, kDigits)
      .AddNumber("rpe_rot_rmse_deg_per_s", has_rpe ? m.rpe.rotation_rmse_deg_per_s : nan, kDigits)
      .AddInteger("rpe_pairs", static_cast<long long>(m.rpe.num_pairs))
      .AddNumber("step_median_m", m.steps.step_m.median, kDigits)
      .AddNumber("step_max_m", m.steps.step_m.max, kDigits)
      .AddNumber("truth_step_median_m", m.steps.truth_step_m.median, kDigits)
      .AddNumber("truth_step_max_m", m.steps.truth_step_m.max, kDigits)
      .AddInteger("associated_poses", static_cast<long long>(m.num_associated))
      .AddInteger("estimated_poses", static_cast<long long>(m.num_estimated))
      .AddInteger("groundtruth_poses", static_cast<long long>(m.num_groundtruth))
      .AddNumber("coverage", c.fraction, kDigits)
      .AddNumber("coverage_covered_s", c.covered_s, kDigits)
      .AddNumber("coverage_span_s", c.span_end_s - c.span_start_s, kDigits);
  return json;
}

// --loops: prints each false loop and the counts, adds them to the JSON.
void CheckLoopFile(const std::string& path, const dslam::Trajectory& groundtruth,
                   dslam::JsonObject* json) {
  const dslam::LoopCheckOptions options;
  const dslam::LoopCheck check = dslam::CheckLoops(dslam::ReadLoopFile(path), groundtruth, options);
  for (const dslam::LoopVerdict& v : check.verdicts) {
    if (!v.checked) {
      std::printf("loop %.6f -> %.6f: no ground truth at its stamps, not checked\n",
                  v.loop.stamp_query_s, v.loop.stamp_match_s);
    } else if (v.false_loop) {
      std::printf("false loop %.6f -> %.6f: off by %.3f m, %.2f deg (cameras %.3f m apart)\n",
                  v.loop.stamp_query_s, v.loop.stamp_match_s, v.translation_error_m,
                  v.rotation_error_deg, v.true_distance_m);
    }
  }
  std::printf("%-24s %-7s %zu (%d checked, %d false; largest error %s m, %s deg)\n", "loops", "",
              check.verdicts.size(), check.checked, check.false_loops,
              Fixed(check.max_translation_error_m, 4).c_str(),
              Fixed(check.max_rotation_error_deg, 3).c_str());
  if (json == nullptr) return;
  json->AddString("loops_file", path)
      .AddInteger("loops", static_cast<long long>(check.verdicts.size()))
      .AddInteger("loops_checked", check.checked)
      .AddInteger("false_loops", check.false_loops)
      .AddNumber("loop_max_translation_error_m", check.max_translation_error_m, 9)
      .AddNumber("loop_max_rotation_error_deg", check.max_rotation_error_deg, 9);
}

// --save-aligned and --save-groundtruth: the pairs the metrics used, the estimate moved by the
// ATE alignment.
void SaveAssociatedPoses(const Arguments& args, const dslam::TrajectoryMetrics& m) {
  const dslam::PoseAssociation& pairs = m.association;
  if (args.values.count("save-aligned")) {
    dslam::Trajectory moved = pairs.estimated;
    for (dslam::StampedPose& pose : moved) {
      pose.T_world_camera = m.T_gtworld_estworld * pose.T_world_camera;
    }
    dslam::WriteTumTrajectory(args.values.at("save-aligned"), moved);
  }
  if (args.values.count("save-groundtruth")) {
    dslam::WriteTumTrajectory(args.values.at("save-groundtruth"), pairs.groundtruth);
  }
}

int Run(const Arguments& args) {
  dslam::TrajectoryMetricsOptions options;
  options.max_association_dt_s = PositiveNumber(args, "max-dt", options.max_association_dt_s);
  options.rpe_interval_s = PositiveNumber(args, "rpe-interval", options.rpe_interval_s);
  options.max_gap_s = PositiveNumber(args, "max-gap", options.max_gap_s);
  dslam::GroundTruthCorrection correction = dslam::GroundTruthCorrection::kNone;
  if (args.values.count("camera")) {
    correction = dslam::LoadCameraYaml(args.values.at("camera")).groundtruth_correction;
  }
  const std::string correction_name =
      correction == dslam::GroundTruthCorrection::kBonn ? "bonn" : "none";
  const dslam::Trajectory groundtruth = dslam::ApplyGroundTruthCorrection(
      dslam::ReadTumTrajectory(args.values.at("groundtruth")), correction);
  if (args.values.count("write-groundtruth")) {
    dslam::WriteTumTrajectory(args.values.at("write-groundtruth"), groundtruth);
  }
  const dslam::Trajectory estimated = dslam::ReadTumTrajectory(args.values.at("trajectory"));
  if (groundtruth.empty()) throw std::runtime_error("ground truth has no poses");
  if (estimated.empty()) throw std::runtime_error("trajectory has no poses");
  std::vector<double> frame_stamps;
  if (args.values.count("frames")) {
    for (const dslam::StampedFile& f : dslam::ReadFileList(args.values.at("frames"))) {
      frame_stamps.push_back(f.stamp_s);
    }
    if (frame_stamps.empty()) throw std::runtime_error("--frames list has no entries");
  }
  const dslam::TrajectoryMetrics metrics =
      dslam::EvaluateTrajectory(estimated, groundtruth, frame_stamps, options);
  PrintTable(metrics, correction_name);
  dslam::JsonObject json = MetricsJson(metrics, args, correction_name, options);
  if (args.values.count("loops")) CheckLoopFile(args.values.at("loops"), groundtruth, &json);
  if (args.values.count("json")) dslam::WriteJsonFile(args.values.at("json"), json);
  SaveAssociatedPoses(args, metrics);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments args;
  try {
    args = ParseArguments(argc, argv);
  } catch (const UsageError& e) {
    std::cerr << "dslam_eval: " << e.what() << " (see dslam_eval --help)\n";
    return 2;
  }
  if (args.help) {
    std::cout << kUsage;
    return 0;
  }
  try {
    return Run(args);
  } catch (const UsageError& e) {
    std::cerr << "dslam_eval: " << e.what() << " (see dslam_eval --help)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "dslam_eval: error: " << e.what() << "\n";
    return 1;
  }
}
