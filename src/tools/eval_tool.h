#pragma once
// What the evaluation tools against a dslam_synth folder (dslam_eval_objects, dslam_eval_map)
// share: `--name value` options, number options, where an estimate's frame lies in the world,
// and main()'s handling of usage errors.

#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "dslam/io/trajectory_io.h"

namespace dslam {
namespace tools {

/// A command-line mistake: main prints it with "(see --help)" and exits with 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Options as `--name value` pairs, by name without the dashes; {{"help", ""}} for --help or
/// -h. Throws UsageError for a name not in `known`, a missing value or a missing `required` one.
using Options = std::map<std::string, std::string>;
Options ParseOptions(int argc, char** argv, const std::vector<std::string>& known,
                     const std::vector<std::string>& required);

/// What a number option must be.
enum class NumberKind {
  kNonNegative,    ///< finite, >= 0
  kPositive,       ///< finite, > 0
  kPositiveWhole,  ///< a whole number in (0, 1e6]
};

/// The option `name` as a number of `kind` (`fallback` when absent); UsageError otherwise.
double NumberOption(const Options& options, const std::string& name, double fallback,
                    NumberKind kind);

/// The dataset folder's ground truth (groundtruth.txt) and T_world_estimate: where the frame of
/// a run's estimates lies in the ground truth's world. The estimates are in the run's
/// trajectory frame, the optical frame of the first frame (smallest stamp of rgb.txt), placed
/// by the ground truth at that stamp, or, with option `trajectory`, by that file's first pose
/// (EstimateFrameInWorld, stamps associated within `max_dt_s`). Throws std::runtime_error when
/// groundtruth.txt or rgb.txt is empty.
struct WorldFrame {
  Trajectory groundtruth;
  Eigen::Isometry3d T_world_estimate = Eigen::Isometry3d::Identity();
};
WorldFrame EstimateWorldFrame(const std::string& folder, const Options& options, double max_dt_s);

/// main() of a tool: parses the options (ParseOptions), prints `usage` for --help, else calls
/// `run`; a UsageError exits with 2, any other exception with 1, each printed after `tool`.
int RunTool(const char* tool, const char* usage, int argc, char** argv,
            const std::vector<std::string>& known, const std::vector<std::string>& required,
            const std::function<int(const Options&)>& run);

}  // namespace tools
}  // namespace dslam
