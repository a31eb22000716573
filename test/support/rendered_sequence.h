#pragma once
// A synthetic scenario rendered in-process (seed 1) for whole-trajectory regression tests: the
// frames, their dynamic masks and the ground-truth trajectory.

#include <string>
#include <utility>
#include <vector>

#include "dslam/core/trajectory.h"
#include "dslam/synth/sequence.h"

namespace dslam {
namespace test {

struct RenderedSequence {
  std::vector<RgbdFrame> frames;
  std::vector<cv::Mat> masks;  ///< per frame: CV_16UC1 moving-object id per pixel, 0 = static
  Trajectory groundtruth;      ///< T_world_camera per frame
};

/// Renders the first `frames` frames of scenario `name` (synth::MakeScenario, seed 1).
inline RenderedSequence RenderSequence(const std::string& name, int frames) {
  const synth::SyntheticSequence sequence(synth::MakeScenario(name, 1));
  RenderedSequence out;
  for (int i = 0; i < frames; ++i) {
    synth::SyntheticFrame frame = sequence.RenderFrame(i);
    out.groundtruth.push_back({frame.frame.stamp_s, frame.T_world_camera});
    out.frames.push_back(std::move(frame.frame));
    out.masks.push_back(std::move(frame.mask));
  }
  return out;
}

}  // namespace test
}  // namespace dslam
