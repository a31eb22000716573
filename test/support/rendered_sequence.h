#pragma once
// A synthetic scenario rendered in-process (seed 1 unless a test asks for another) for whole-trajectory regression tests: the
// frames, their dynamic masks and the ground-truth trajectory; SharedSequence renders one once for
// all the tests of a binary, TrackAll feeds its frames to a tracker.

#include <cstddef>
#include <cstdlib>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "dslam/core/config.h"
#include "dslam/core/trajectory.h"
#include "dslam/synth/sequence.h"
#include "support/scene_cache.h"

namespace dslam {
namespace test {

struct RenderedSequence {
  std::vector<RgbdFrame> frames;
  std::vector<cv::Mat> masks;  ///< per frame: CV_16UC1 moving-object id per pixel, 0 = static
  Trajectory groundtruth;      ///< T_world_camera per frame
  synth::SensorParams sensor;  ///< the scenario's camera, its depth noise included
};

/// `config` with the depth model of `sequence`'s sensor (synth::UseSensorDepthNoise), as
/// dslam_run_dataset reads it from the camera.yaml dslam_synth writes.
inline Config SensorConfig(const RenderedSequence& sequence, Config config = Config()) {
  synth::UseSensorDepthNoise(sequence.sensor, &config.depth_noise);
  return config;
}

/// The images of frames 0..frames-1 of `sequence`: rendered, or read from
/// $DSLAM_TEST_SCENES/<name>_s<seed>.bin when the environment names that folder (scripts/test.sh sets
/// a new one per run) and the file holds enough frames; a file with fewer is replaced by one with
/// `frames` (written to a file of its own, then renamed: binaries running at the same time read
/// whole files). The images are the same bit for bit either way.
inline std::vector<CachedImages> SceneImages(const synth::SyntheticSequence& sequence,
                                             const std::string& name, int frames, int seed,
                                             bool cache = true) {
  const char* folder = cache ? std::getenv("DSLAM_TEST_SCENES") : nullptr;
  const std::string file = name + "_s" + std::to_string(seed) + ".bin";
  const std::string path = folder && *folder ? std::string(folder) + "/" + file : "";
  std::vector<CachedImages> images;
  if (!path.empty()) images = ReadSceneCache(path, frames);
  if (static_cast<int>(images.size()) == frames) return images;
  images.clear();
  for (int i = 0; i < frames; ++i) {
    synth::SyntheticFrame frame = sequence.RenderFrame(i);
    images.push_back({frame.frame.colour, frame.frame.depth_m, frame.mask});
  }
  // Another binary may have written more frames meanwhile: keep the longer file.
  if (!path.empty() && CachedFrameCount(path) < frames) WriteSceneCache(path, images);
  return images;
}

/// Renders the first `frames` frames of scenario `name` (synth::MakeScenario with `seed`); stamps,
/// poses and the camera are the sequence's (SyntheticSequence::RenderFrame sets the same).
/// `cache` false: never read or write $DSLAM_TEST_SCENES (a long sequence one binary uses).
inline RenderedSequence RenderSequence(const std::string& name, int frames, int seed = 1,
                                       bool cache = true) {
  const synth::SyntheticSequence sequence(synth::MakeScenario(name, seed));
  std::vector<CachedImages> images = SceneImages(sequence, name, frames, seed, cache);
  RenderedSequence out;
  out.sensor = sequence.scenario().sensor;
  for (int i = 0; i < frames; ++i) {
    RgbdFrame frame;
    frame.stamp_s = sequence.StampOf(i);
    frame.colour = std::move(images[i].colour);
    frame.depth_m = std::move(images[i].depth_m);
    frame.camera = sequence.camera();
    out.groundtruth.push_back({frame.stamp_s, sequence.PoseOf(i)});
    out.frames.push_back(std::move(frame));
    out.masks.push_back(std::move(images[i].mask));
  }
  return out;
}

/// Feeds `frames` in order to `tracker` (anything with ProcessFrame(const RgbdFrame&) returning a
/// FrameResult: Odometry, Slam) and calls on_result(i, result) after frame i; returns the poses
/// it reported (has_pose): stamp and T_world_camera per frame.
template <typename Tracker, typename OnResult>
Trajectory TrackAll(Tracker* tracker, const std::vector<RgbdFrame>& frames, OnResult on_result) {
  Trajectory estimated;
  for (size_t i = 0; i < frames.size(); ++i) {
    const auto result = tracker->ProcessFrame(frames[i]);
    if (result.has_pose) estimated.push_back({result.stamp_s, result.T_world_camera});
    on_result(i, result);
  }
  return estimated;
}

/// RenderSequence(name, frames), rendered on the first call with these arguments in this process;
/// every call returns that one object, which lives until the process ends (for the tests of a
/// binary that share a sequence: rendering is the slow part). Safe to call from any thread.
inline const RenderedSequence& SharedSequence(const std::string& name, int frames) {
  static std::mutex mutex;
  static std::map<std::pair<std::string, int>, RenderedSequence> rendered;
  const std::lock_guard<std::mutex> lock(mutex);
  const std::pair<std::string, int> key(name, frames);
  auto found = rendered.find(key);
  if (found == rendered.end()) found = rendered.emplace(key, RenderSequence(name, frames)).first;
  return found->second;
}

}  // namespace test
}  // namespace dslam
