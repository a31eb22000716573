#include "eval_tool.h"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "dslam/eval/trajectory_metrics.h"
#include "dslam/io/dataset_io.h"

namespace dslam {
namespace tools {

Options ParseOptions(int argc, char** argv, const std::vector<std::string>& known,
                     const std::vector<std::string>& required) {
  Options values;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") return {{"help", ""}};
    const std::string name = arg.rfind("--", 0) == 0 ? arg.substr(2) : "";
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      throw UsageError("unknown argument '" + arg + "'");
    }
    if (i + 1 >= argc) throw UsageError("missing value after " + arg);
    values[name] = argv[++i];
  }
  for (const std::string& name : required) {
    if (!values.count(name)) throw UsageError("--" + name + " is required");
  }
  return values;
}

double NumberOption(const Options& options, const std::string& name, double fallback,
                    NumberKind kind) {
  const auto it = options.find(name);
  if (it == options.end()) return fallback;
  size_t used = 0;
  double value = -1.0;
  try {
    value = std::stod(it->second, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  const bool parsed = used == it->second.size() && std::isfinite(value);
  if (kind == NumberKind::kNonNegative) {
    if (!parsed || !(value >= 0.0)) {
      throw UsageError("--" + name + " needs a number >= 0, got '" + it->second + "'");
    }
    return value;
  }
  const bool whole = kind == NumberKind::kPositiveWhole;
  if (!parsed || !(value > 0.0) || (whole && (value != std::floor(value) || value > 1e6))) {
    throw UsageError("--" + name + " needs a positive " + (whole ? "whole " : "") +
                     "number, got '" + it->second + "'");
  }
  return value;
}

WorldFrame EstimateWorldFrame(const std::string& folder, const Options& options, double max_dt_s) {
  WorldFrame world;
  world.groundtruth = ReadTumTrajectory(folder + "/groundtruth.txt");
  const std::vector<StampedFile> frames = ReadFileList(folder + "/rgb.txt");
  if (world.groundtruth.empty() || frames.empty()) {
    throw std::runtime_error(folder + ": groundtruth.txt or rgb.txt is empty");
  }
  double first_stamp = frames.front().stamp_s;
  for (const StampedFile& f : frames) first_stamp = std::min(first_stamp, f.stamp_s);
  const Trajectory estimated =
      options.count("trajectory") ? ReadTumTrajectory(options.at("trajectory")) : Trajectory();
  world.T_world_estimate =
      EstimateFrameInWorld(world.groundtruth, first_stamp, estimated, max_dt_s);
  return world;
}

int RunTool(const char* tool, const char* usage, int argc, char** argv,
            const std::vector<std::string>& known, const std::vector<std::string>& required,
            const std::function<int(const Options&)>& run) {
  try {
    const Options options = ParseOptions(argc, argv, known, required);
    if (options.count("help")) {
      std::cout << usage;
      return 0;
    }
    return run(options);
  } catch (const UsageError& e) {
    std::cerr << tool << ": " << e.what() << " (see --help)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << tool << ": error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace tools
}  // namespace dslam
