#pragma once
// dslam_run_dataset's command line: the options, their parsing and the usage text.

#include <string>

namespace dslam {
namespace tools {

/// The options of dslam_run_dataset (file paths empty: not written).
struct RunDatasetArgs {
  std::string dataset, camera, trajectory, status, config, summary, segmentation;
  std::string refined_trajectory;  ///< every frame on its reference keyframe after the last BA
  std::string objects;             ///< moving objects file (objects_output.h)
  std::string map;                 ///< static map PCD (map_output.h)
  std::string map_unmasked;        ///< the same fusion without masks and free-space check, PCD
  std::string static_points;       ///< "on", "off" or empty (the config's static_points.enabled)
  std::string backend;             ///< "on", "off" or empty (the config's backend.enabled)
  int max_frames = -1;
  bool quiet = false;
  bool threads = false;  ///< the back end on its own thread (BackEndMode::kThreaded)
  /// [Hz] --rate: frame i is handed over no earlier than start + i / rate_hz; 0: at once.
  double rate_hz = 0.0;
};

/// Prints the usage to stderr; returns the exit status 2.
int Usage();

/// Parses argv into `args`; false when an option is unknown, lacks its value or has a bad one,
/// or --dataset or --trajectory is missing. Throws std::exception from std::stoi / std::stod when
/// a number does not parse.
bool Parse(int argc, char** argv, RunDatasetArgs* args);

}  // namespace tools
}  // namespace dslam
