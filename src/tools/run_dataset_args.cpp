#include "run_dataset_args.h"

#include <iostream>

namespace dslam {
namespace tools {

int Usage() {
  std::cerr
      << "usage: dslam_run_dataset --dataset FOLDER --trajectory OUT.txt [--camera "
         "camera.yaml]\n"
         "                         [--status OUT.csv] [--static-points on|off] "
         "[--backend on|off] [--config params.yaml]\n"
         "                         [--summary OUT.json] [--segmentation OUT.csv] "
         "[--max-frames N] [--quiet]\n"
         "                         [--refined-trajectory OUT.txt] [--threads] [--rate HZ]\n"
         "                         [--objects OUT.txt] [--map OUT.pcd] "
         "[--map-unmasked OUT.pcd] [--grid OUT.yaml] [--octomap OUT.bt]\n"
         "                         [--loop-closing on|off] [--loops OUT.txt] "
         "[--vocabulary FILE]\n"
         "                         [--save-keyframe-map OUT.bin] [--load-keyframe-map IN.bin]\n"
         "                         [--localise-timeout-s S (10)] [--localisation-only]\n";
  return 2;
}

bool Parse(int argc, char** argv, RunDatasetArgs* args) {
  for (int i = 1; i < argc; ++i) {
    const std::string key = argv[i];
    if (key == "--quiet") {
      args->quiet = true;
      continue;
    }
    if (key == "--threads") {
      args->threads = true;
      continue;
    }
    if (key == "--localisation-only") {
      args->localisation_only = true;
      continue;
    }
    if (i + 1 >= argc) return false;
    const std::string value = argv[++i];
    if (key == "--dataset")
      args->dataset = value;
    else if (key == "--camera")
      args->camera = value;
    else if (key == "--trajectory")
      args->trajectory = value;
    else if (key == "--objects")
      args->objects = value;
    else if (key == "--map")
      args->map = value;
    else if (key == "--grid")
      args->grid = value;
    else if (key == "--octomap")
      args->octomap = value;
    else if (key == "--map-unmasked")
      args->map_unmasked = value;
    else if (key == "--refined-trajectory")
      args->refined_trajectory = value;
    else if (key == "--status")
      args->status = value;
    else if (key == "--config")
      args->config = value;
    else if (key == "--summary")
      args->summary = value;
    else if (key == "--segmentation")
      args->segmentation = value;
    else if (key == "--max-frames")
      args->max_frames = std::stoi(value);
    else if (key == "--rate" && std::stod(value) > 0.0)
      args->rate_hz = std::stod(value);
    else if (key == "--static-points" && (value == "on" || value == "off"))
      args->static_points = value;
    else if (key == "--backend" && (value == "on" || value == "off"))
      args->backend = value;
    else if (key == "--loop-closing" && (value == "on" || value == "off"))
      args->loop_closing = value;
    else if (key == "--loops")
      args->loops = value;
    else if (key == "--vocabulary")
      args->vocabulary = value;
    else if (key == "--save-keyframe-map")
      args->save_keyframe_map = value;
    else if (key == "--load-keyframe-map")
      args->load_keyframe_map = value;
    else if (key == "--localise-timeout-s" && std::stod(value) > 0.0)
      args->localise_timeout_s = std::stod(value);
    else
      return false;
  }
  return !args->dataset.empty() && !args->trajectory.empty();
}

std::string CheckCombination(const RunDatasetArgs& args) {
  if (args.localisation_only && args.load_keyframe_map.empty()) {
    return "--localisation-only needs --load-keyframe-map (a map to localise in)";
  }
  return "";
}

}  // namespace tools
}  // namespace dslam
