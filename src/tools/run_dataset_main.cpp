// dslam_run_dataset: runs dslam (front end and, after keyframes, the back end; synchronous and
// deterministic by default, or with the back end on its own thread as in the ROS node) on a
// TUM-layout folder, optionally at a fixed frame rate, and writes the trajectory (every tracked
// frame's pose as estimated at that frame, TUM format, camera optical frame), a per-frame status
// CSV and a summary. On synthetic folders (mask.txt present) it also scores the labels. Options:
// run_dataset_args.h; moving objects: objects_output.h; static maps: map_output.h; the keyframe
// map file: keyframe_map_output.h.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include <opencv2/imgcodecs.hpp>

#include "dslam/backend/slam.h"
#include "dslam/eval/json_writer.h"
#include "dslam/eval/quantile.h"
#include "dslam/eval/run_statistics.h"
#include "dslam/eval/segmentation_score.h"
#include "dslam/eval/status_table.h"
#include "dslam/io/config_io.h"
#include "dslam/io/dataset_io.h"
#include "dslam/io/trajectory_io.h"
#include "keyframe_map_output.h"
#include "loop_output.h"
#include "map_output.h"
#include "objects_output.h"
#include "run_dataset_args.h"
#include "run_progress.h"

namespace {

using Args = dslam::tools::RunDatasetArgs;

// Masks by colour stamp (synthetic folders); empty when the folder has no mask.txt.
std::map<double, std::string> ReadMasks(const std::string& folder) {
  std::map<double, std::string> masks;
  std::ifstream probe(folder + "/mask.txt");
  if (!probe) return masks;
  for (const auto& f : dslam::ReadFileList(folder + "/mask.txt")) masks[f.stamp_s] = f.path;
  return masks;
}

// One frame's confusion counts (--segmentation).
void WriteSegmentationRow(int frame, const dslam::SegmentationScore& s, std::ofstream* out) {
  *out << frame << ',' << s.true_dynamic() << ',' << s.false_dynamic() << ',' << s.missed_dynamic()
       << ',' << s.true_static() << ',' << s.candidates_on_dynamic() << ','
       << s.candidates_on_static() << '\n';
}

// The run's numbers as JSON (scripts/benchmark.py reads it).
// `scored`: the folder has masks; "static_points" is config.static_points.enabled.
dslam::JsonObject SummaryJson(const dslam::RunSummary& summary,
                              const dslam::SegmentationScore& score, bool scored,
                              const dslam::Config& config, const Args& args) {
  constexpr int kDigits = 6;  // significant digits of every number
  dslam::JsonObject json;
  json.AddInteger("frames", summary.frames())
      .AddInteger("frames_with_pose", summary.frames_with_pose())
      .AddInteger("lost_frames", summary.lost_frames())
      .AddInteger("localising_frames", summary.localising_frames())
      .AddBool("static_points", config.static_points.enabled)
      .AddBool("backend", config.backend.enabled)
      .AddBool("threads", args.threads)
      .AddNumber("rate_hz", args.rate_hz, kDigits)
      .AddNumber("median_graph_points", summary.MedianGraphPoints(), kDigits)
      .AddNumber("labelled_dynamic_share", summary.LabelledDynamicShare(), kDigits);
  for (const char* stage :
       {"features", "matching", "initial_pose", "static_points", "refine", "mapping", "total"}) {
    json.AddNumber(std::string("median_") + stage + "_ms", summary.MedianMs(stage), kDigits);
  }
  json.AddNumber("median_frame_ms", summary.MedianFrameMs(), kDigits)
      .AddNumber("median_tracking_ms", summary.TrackingQuantile(0.5), kDigits)
      .AddNumber("p95_tracking_ms", summary.TrackingQuantile(0.95), kDigits)
      .AddInteger("backend_runs", summary.backend_runs())
      .AddInteger("max_backlog", summary.max_backlog());
  dslam::AddBackEndQuantiles(summary, kDigits, &json);
  if (!scored) return json;
  json.AddNumber("dynamic_precision", score.Precision(), kDigits)
      .AddNumber("dynamic_recall", score.Recall(), kDigits)
      .AddNumber("false_dynamic_rate", score.FalseDynamicRate(), kDigits)
      .AddInteger("true_dynamic", score.true_dynamic())
      .AddInteger("false_dynamic", score.false_dynamic())
      .AddInteger("missed_dynamic", score.missed_dynamic())
      .AddInteger("true_static", score.true_static())
      .AddInteger("candidates_on_dynamic", score.candidates_on_dynamic())
      .AddInteger("candidates_on_static", score.candidates_on_static());
  return json;
}

// Everything a run collects while frames are processed.
struct Outputs {
  dslam::Trajectory trajectory;  ///< causal poses
  dslam::RunSummary summary;
  dslam::SegmentationScore score;
  std::map<double, std::string> masks;  ///< mask image by colour stamp; empty: not synthetic
  std::ofstream status, segmentation;   ///< the CSVs asked for (closed when not)
  std::unique_ptr<dslam::tools::ObjectsOutput> objects;  ///< --objects
};

// Reads the masks and opens the CSVs the arguments ask for, with their headers.
void OpenOutputs(const Args& args, const dslam::Config& config, Outputs* out) {
  out->masks = ReadMasks(args.dataset);
  if (!args.objects.empty()) {
    out->objects = std::make_unique<dslam::tools::ObjectsOutput>(
        args.objects, config,
        args.threads ? dslam::WorkerMode::kThreaded : dslam::WorkerMode::kSynchronous);
  }
  if (!args.status.empty()) {
    out->status.open(args.status);
    out->status << dslam::StatusCsvHeader() << "\n";
  }
  if (!args.segmentation.empty() && !out->masks.empty()) {
    out->segmentation.open(args.segmentation);
    out->segmentation << "frame,true_dynamic,false_dynamic,missed_dynamic,true_static,"
                         "candidates_on_dynamic,candidates_on_static\n";
  }
}

// Prints the errors `log` took since the last call (each once, where it happened) to stderr.
void PrintNewErrors(dslam::ErrorLog* log) {
  if (log == nullptr) return;
  for (const dslam::ReportedError& error : log->TakeNew()) {
    std::fprintf(stderr, "dslam_run_dataset: error in %s: %s\n", error.where.c_str(),
                 error.what.c_str());
  }
}

// Adds one frame's result to the trajectory, summary, CSVs and segmentation score.
void Record(const Args& args, const dslam::FrameResult& r, Outputs* out) {
  out->summary.Add(r);
  if (r.has_pose) out->trajectory.push_back({r.stamp_s, r.T_world_camera});
  if (out->status) out->status << dslam::StatusCsvRow(r) << "\n";
  const auto mask = out->masks.find(r.stamp_s);
  if (mask == out->masks.end()) return;
  dslam::SegmentationScore frame_score;
  frame_score.Add(r.points, cv::imread(args.dataset + "/" + mask->second, cv::IMREAD_ANYDEPTH));
  out->score.Merge(frame_score);
  if (out->segmentation) WriteSegmentationRow(r.frame_index, frame_score, &out->segmentation);
}

// Hands every frame to `slam` (frame i no earlier than start + i / rate_hz with --rate; a late
// frame is not dropped) and records it; then waits for the back end and records the runs no
// frame reported.
void FeedFrames(const Args& args, const dslam::TumDataset& dataset, dslam::Slam* slam,
                Outputs* out) {
  const size_t n =
      args.max_frames < 0 ? dataset.size() : std::min<size_t>(dataset.size(), args.max_frames);
  const auto start = std::chrono::steady_clock::now();
  dslam::tools::FrameMessages messages;
  for (size_t i = 0; i < n; ++i) {
    const dslam::RgbdFrame frame = dataset.LoadFrame(i);
    if (args.rate_hz > 0.0) {
      std::this_thread::sleep_until(start +
                                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                        std::chrono::duration<double>(i / args.rate_hz)));
    }
    const dslam::FrameResult r = slam->ProcessFrame(frame);
    PrintNewErrors(slam->errors().get());
    if (out->objects) out->objects->Add(frame, r);
    Record(args, r, out);
    if (!args.quiet) {
      messages.Add(r);
      dslam::tools::Progress(i + 1, n, r);
    }
  }
  messages.Flush();
  slam->WaitForBackEnd();
  for (const dslam::BackEndStatus& run : slam->TakeUnreportedRuns()) out->summary.AddBackEnd(run);
  if (!args.quiet && isatty(fileno(stderr))) std::fprintf(stderr, "\n");
}

// The stage table, the segmentation score (synthetic folders) and the summary line.
void PrintReport(const Args& args, const dslam::Config& config, const Outputs& out) {
  const dslam::RunSummary& summary = out.summary;
  const dslam::SegmentationScore& score = out.score;
  summary.PrintStages(std::cout);
  if (!out.masks.empty()) {
    std::printf(
        "segmentation: dynamic precision %.3f recall %.3f, static wrongly dynamic %.4f "
        "(tp %ld fp %ld fn %ld tn %ld; not yet judged: %ld on objects, %ld static)\n",
        score.Precision(), score.Recall(), score.FalseDynamicRate(), score.true_dynamic(),
        score.false_dynamic(), score.missed_dynamic(), score.true_static(),
        score.candidates_on_dynamic(), score.candidates_on_static());
  }
  std::string backend = config.backend.enabled ? "on" : "off";
  if (config.backend.enabled && args.threads) {
    backend += " (thread, max backlog " + std::to_string(summary.max_backlog()) + ")";
  }
  std::printf(
      "summary: %d frames, %d with pose (%.1f%%), %d lost, static points %s, back end %s, "
      "median %.1f ms/frame (front end %.1f, tracking thread %.1f) -> %s\n",
      summary.frames(), summary.frames_with_pose(),
      100.0 * summary.frames_with_pose() / std::max(1, summary.frames()), summary.lost_frames(),
      config.static_points.enabled ? "on" : "off", backend.c_str(), summary.MedianFrameMs(),
      summary.MedianMs("total"), summary.TrackingQuantile(0.5), args.trajectory.c_str());
}

// The vocabulary of the run (--vocabulary, default the committed one) when loop closing or a
// keyframe map file needs it; null otherwise.
std::shared_ptr<const dslam::Vocabulary> RunVocabulary(const Args& args,
                                                       const dslam::Config& config) {
  const bool loop_closing = config.loop_closing.enabled && config.backend.enabled;
  if (!loop_closing && args.save_keyframe_map.empty() && args.load_keyframe_map.empty()) {
    return nullptr;
  }
  const std::string path =
      args.vocabulary.empty() ? dslam::DefaultVocabularyPath() : args.vocabulary;
  return std::make_shared<const dslam::Vocabulary>(dslam::Vocabulary::Load(path));
}

int Run(const Args& args) {
  // The camera's depth noise (camera.yaml, when it states one) replaces the defaults' real-camera
  // model; a --config file's depth_noise keys replace both.
  dslam::Config config;
  const std::string camera_yaml = dslam::CameraYamlPath(args.dataset, args.camera);
  if (dslam::UseCameraDepthNoise(dslam::LoadCameraYaml(camera_yaml), &config.depth_noise) &&
      !args.quiet) {
    std::printf("depth noise from %s: %g d^2 + %g m\n", camera_yaml.c_str(),
                config.depth_noise.sigma_d_quadratic, config.depth_noise.sigma_d_constant_m);
  }
  if (!args.config.empty()) dslam::LoadConfigYaml(args.config, &config);
  if (!args.static_points.empty()) config.static_points.enabled = args.static_points == "on";
  if (!args.backend.empty()) config.backend.enabled = args.backend == "on";
  if (!args.loop_closing.empty()) config.loop_closing.enabled = args.loop_closing == "on";
  if (args.loop_closing == "on" && !config.backend.enabled) {
    std::fprintf(stderr, "dslam_run_dataset: loop closing needs the back end: off\n");
  }
  const dslam::TumDataset dataset(args.dataset, args.camera, config.dataset.association_max_dt_s);
  dslam::tools::MapOutput maps(args.map, args.map_unmasked, args.grid, args.octomap, config);
  const std::shared_ptr<const dslam::Vocabulary> vocabulary = RunVocabulary(args, config);
  dslam::tools::LoopOutput loops(
      config, vocabulary,
      args.threads ? dslam::WorkerMode::kThreaded : dslam::WorkerMode::kSynchronous);
  std::vector<std::shared_ptr<dslam::KeyFrameObserver>> observers = maps.Observers();
  for (auto& observer : loops.Observers()) observers.push_back(observer);
  dslam::tools::KeyFrameMapOutput keyframe_map(args.save_keyframe_map, vocabulary);
  for (auto& observer : keyframe_map.Observers()) observers.push_back(observer);
  dslam::Slam slam(config,
                   args.threads ? dslam::BackEndMode::kThreaded : dslam::BackEndMode::kSynchronous,
                   dslam::RefinedPoseRecording::kOn, observers);
  loops.Attach(&slam);
  keyframe_map.Attach(&slam);
  keyframe_map.Load(args.load_keyframe_map, dataset.camera_yaml().camera, args.localise_timeout_s,
                    args.localisation_only ? dslam::LoadedMapUse::kLocalisationOnly
                                           : dslam::LoadedMapUse::kExtend,
                    &slam);
  Outputs out;
  OpenOutputs(args, config, &out);
  FeedFrames(args, dataset, &slam, &out);
  loops.Wait();
  slam.WaitForBackEnd();  // the last loop's correction reaches the observers (the static map)
  PrintNewErrors(slam.errors().get());
  PrintNewErrors(loops.errors().get());
  if (out.objects) out.objects->Close();
  maps.Write();
  loops.Write(args.loops);
  keyframe_map.Save(slam, *dataset.camera_yaml().camera);
  dslam::WriteTumTrajectory(args.trajectory, out.trajectory);
  if (!args.refined_trajectory.empty()) {
    dslam::WriteTumTrajectory(args.refined_trajectory, slam.RefinedPoses());
  }
  PrintReport(args, config, out);
  if (out.objects) {
    std::printf("objects: %d object-frames, median %.2f ms/frame (mask and tracking) -> %s\n",
                out.objects->object_frames(), dslam::Median(out.objects->times_ms()),
                args.objects.c_str());
  }
  maps.Print();
  loops.Print();
  keyframe_map.Print();
  if (!args.summary.empty()) {
    dslam::JsonObject json = SummaryJson(out.summary, out.score, !out.masks.empty(), config, args);
    maps.AddTo(&json);
    loops.AddTo(&json);
    json.AddNumber("max_map_lock_ms", slam.TakeLongestMapLockHold().ms, 6);
    json.AddInteger("errors",
                    slam.errors()->count() + (loops.errors() ? loops.errors()->count() : 0));
    keyframe_map.AddTo(&json);
    if (out.objects) {  // --objects: their work per frame, and the tracking thread's share of it
      json.AddNumber("median_objects_ms", dslam::Median(out.objects->times_ms()), 6)
          .AddNumber("p95_objects_ms", dslam::Quantile(out.objects->times_ms(), 0.95), 6)
          .AddNumber("median_objects_add_ms", dslam::Median(out.objects->add_times_ms()), 6)
          .AddInteger("object_frames", out.objects->object_frames());
    }
    dslam::WriteJsonFile(args.summary, json);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  bool parsed = false;
  try {
    parsed = dslam::tools::Parse(argc, argv, &args);
  } catch (const std::exception&) {  // a number that does not parse (std::stoi, std::stod)
  }
  if (!parsed) return dslam::tools::Usage();
  const std::string combination = dslam::tools::CheckCombination(args);
  if (!combination.empty()) {
    std::cerr << "dslam_run_dataset: " << combination << "\n";
    return dslam::tools::Usage();
  }
  try {
    return Run(args);
  } catch (const std::exception& e) {
    std::cerr << "dslam_run_dataset: " << e.what() << "\n";
    return 1;
  }
}
