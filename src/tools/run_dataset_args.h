#pragma once
// dslam_run_dataset's command line: the options, their parsing and the usage text
// (docs/tools-and-data.md's option table describes each).

#include <string>

namespace dslam {
namespace tools {

/// The options of dslam_run_dataset. A file path left empty: that file is not written.
struct RunDatasetArgs {
  std::string dataset;       ///< --dataset: TUM-layout folder (required)
  std::string camera;        ///< --camera: camera.yaml; empty: FOLDER/camera.yaml
  std::string trajectory;    ///< --trajectory: causal poses, TUM format (required)
  std::string status;        ///< --status: per-frame CSV
  std::string config;        ///< --config: YAML with parameters to override
  std::string summary;       ///< --summary: the run's numbers as JSON
  std::string segmentation;  ///< --segmentation: per-frame label scores (synthetic folders)
  /// --refined-trajectory: every frame on its reference keyframe after the last BA.
  std::string refined_trajectory;
  std::string objects;  ///< --objects: moving objects file (objects_output.h)
  std::string map;      ///< --map: static map PCD (map_output.h)
  std::string grid;     ///< --grid: occupancy grid YAML and PGM (map_output.h)
  std::string octomap;  ///< --octomap: OctoMap binary file (map_output.h)
  /// --map-unmasked: the same fusion without masks and free-space check, PCD.
  std::string map_unmasked;
  std::string static_points;  ///< --static-points: "on", "off" or empty (the config's value)
  std::string backend;        ///< --backend: "on", "off" or empty (the config's value)
  /// --loop-closing: "on", "off" or empty (the config's value); on needs the back end.
  std::string loop_closing;
  std::string loops;       ///< --loops: accepted loops, one per line (io/loop_io.h)
  std::string vocabulary;  ///< --vocabulary: vocabulary file; empty: the committed one
  /// --save-keyframe-map: the final keyframe map file (keyframe_map_output.h)
  std::string save_keyframe_map;
  /// --load-keyframe-map: start in this keyframe map file (keyframe_map_output.h)
  std::string load_keyframe_map;
  /// [s] --localise-timeout-s: without a frame localised in the loaded map this long after the
  /// first frame, a new map starts (Odometry::StartInMap)
  double localise_timeout_s = 10.0;
  /// --localisation-only: track in the loaded map without changing it
  /// (LoadedMapUse::kLocalisationOnly); needs --load-keyframe-map
  bool localisation_only = false;
  int max_frames = -1;   ///< --max-frames: process only the first N frames; -1: all
  bool quiet = false;    ///< --quiet: no progress bar
  bool threads = false;  ///< --threads: the back end on its own thread (kThreaded)
  /// [Hz] --rate: frame i is handed over no earlier than start + i / rate_hz; 0: at once.
  double rate_hz = 0.0;
};

/// Prints the usage to stderr; returns the exit status 2.
int Usage();

/// Parses argv into `args`; false when an option is unknown, lacks its value or has a bad one,
/// or --dataset or --trajectory is missing. Throws std::exception from std::stoi / std::stod when
/// a number does not parse.
bool Parse(int argc, char** argv, RunDatasetArgs* args);

/// Why options that parsed cannot go together ("--localisation-only needs
/// --load-keyframe-map"), or "" when they can.
std::string CheckCombination(const RunDatasetArgs& args);

}  // namespace tools
}  // namespace dslam
