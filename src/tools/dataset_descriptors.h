#pragma once
// Frames of TUM-layout folders for the place-recognition tools (dslam_train_vocabulary,
// dslam_place_recognition_eval): frame ranges and each frame's ORB descriptors, extracted as the
// tracker extracts them (ExtractFeatures with the Config's features and depth noise).

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "dslam/core/config.h"
#include "dslam/io/dataset_io.h"

namespace dslam {
namespace tools {

/// Frames first, first + step, ... up to last (inclusive; -1: the dataset's last frame).
struct FrameRange {
  int first = 0;
  int last = -1;
  int step = 1;
};

/// Parses "FIRST:LAST:STEP" (LAST -1 for the end); throws UsageError (eval_tool.h) otherwise.
FrameRange ParseFrameRange(const std::string& text);

/// The indices of `range` below `size` (associated pairs of a dataset).
std::vector<int> FrameIndices(const FrameRange& range, size_t size);

/// ORB descriptors (CV_8UC1, 32 columns) of frame `index`: ExtractFeatures(frame,
/// config.features, config.depth_noise).descriptors.
cv::Mat FrameDescriptors(const TumDataset& dataset, int index, const Config& config);

}  // namespace tools
}  // namespace dslam
