// dslam_synth: renders a synthetic RGB-D sequence in the TUM layout (see docs/readme/synth.md).
//   dslam_synth --scenario NAME [--frames N] [--seed S] [--camera MOTION] --output FOLDER
//               [--bag OUT.bag]   (then converts FOLDER with `rosrun dslam tum_to_bag`)
//   dslam_synth --scenario NAME [--seed S] --preview OUT.png [--preview-frame K]
//   dslam_synth --list
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "dslam/synth/writer.h"

namespace {

void PrintUsage() {
  std::cerr << "usage: dslam_synth --scenario NAME [--frames N] [--seed S] [--camera "
               "static|xyz|rpy|halfsphere|tour]\n"
               "                   [--output FOLDER [--bag OUT.bag]] [--preview OUT.png "
               "[--preview-frame K]]\n"
               "       dslam_synth --list\n";
}

int Run(const std::map<std::string, std::string>& args) {
  using namespace dslam::synth;
  if (args.count("list")) {
    for (const auto& [name, description] : ScenarioNames()) {
      std::printf("%-20s %s\n", name.c_str(), description.c_str());
    }
    return 0;
  }
  if (!args.count("scenario") || (!args.count("output") && !args.count("preview"))) {
    PrintUsage();
    return 2;
  }
  const uint32_t seed = args.count("seed") ? std::stoul(args.at("seed")) : 1;
  Scenario scenario = MakeScenario(args.at("scenario"), seed);
  if (args.count("camera")) scenario.camera.kind = ParseCameraMotion(args.at("camera"));
  const int frames = args.count("frames") ? std::stoi(args.at("frames")) : scenario.frames;
  const SyntheticSequence sequence(scenario);
  if (args.count("preview")) {
    const int k = args.count("preview-frame") ? std::stoi(args.at("preview-frame")) : 60;
    const cv::Mat panel = MakePreviewPanel(sequence.RenderFrame(k), scenario.sensor.max_depth_m);
    if (!cv::imwrite(args.at("preview"), panel)) throw std::runtime_error("cannot write preview");
    std::printf("preview of frame %d written to %s\n", k, args.at("preview").c_str());
  }
  if (!args.count("output")) return 0;
  std::printf("rendering %s (seed %u, camera %s): %d frames -> %s\n", scenario.name.c_str(), seed,
              CameraMotionName(scenario.camera.kind).c_str(), frames, args.at("output").c_str());
  const WriteSummary s =
      WriteSequence(sequence, args.at("output"), frames, [](int done, int total) {
        if (done % 30 == 0 || done == total) std::printf("  %d/%d frames\n", done, total);
        std::fflush(stdout);
      });
  std::printf(
      "done: %d frames in %.1f s (%.1f ms/frame); dynamic coverage mean %.3f min %.3f max "
      "%.3f\n",
      s.frames, s.seconds, 1000.0 * s.seconds / std::max(1, s.frames), s.coverage_mean,
      s.coverage_min, s.coverage_max);
  if (args.count("bag")) {
    // The bag is made by the package's tum_to_bag (needs the ROS environment, as rosrun gives).
    const std::string command =
        "rosrun dslam tum_to_bag '" + args.at("output") + "' '" + args.at("bag") + "'";
    std::printf("converting: %s\n", command.c_str());
    std::fflush(stdout);
    if (std::system(command.c_str()) != 0) throw std::runtime_error("tum_to_bag failed");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> args;
  for (int i = 1; i < argc; ++i) {
    std::string key = argv[i];
    if (key.rfind("--", 0) != 0) {
      PrintUsage();
      return 2;
    }
    key = key.substr(2);
    static const std::set<std::string> kKnown = {"scenario", "frames", "seed",    "camera",
                                                 "output",   "bag",    "preview", "preview-frame",
                                                 "list",     "help"};
    if (!kKnown.count(key)) {
      std::cerr << "dslam_synth: unknown option --" << key << "\n";
      PrintUsage();
      return 2;
    }
    if (key == "list" || key == "help") {
      args[key] = "";
    } else if (i + 1 < argc) {
      args[key] = argv[++i];
    } else {
      PrintUsage();
      return 2;
    }
  }
  if (args.count("help")) {
    PrintUsage();
    return 0;
  }
  try {
    return Run(args);
  } catch (const std::exception& e) {
    std::cerr << "dslam_synth: " << e.what() << "\n";
    return 1;
  }
}
