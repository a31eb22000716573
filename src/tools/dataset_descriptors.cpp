#include "dataset_descriptors.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "dslam/features/features.h"
#include "eval_tool.h"

namespace dslam {
namespace tools {

FrameRange ParseFrameRange(const std::string& text) {
  std::istringstream in(text);
  FrameRange range;
  char colon1 = 0;
  char colon2 = 0;
  if (!(in >> range.first >> colon1 >> range.last >> colon2 >> range.step) || colon1 != ':' ||
      colon2 != ':' || !in.eof() || range.first < 0 || range.step < 1) {
    throw UsageError("frame range '" + text + "': expected FIRST:LAST:STEP");
  }
  return range;
}

std::vector<int> FrameIndices(const FrameRange& range, size_t size) {
  const int last = range.last < 0 ? static_cast<int>(size) - 1
                                  : std::min(range.last, static_cast<int>(size) - 1);
  std::vector<int> indices;
  for (int i = range.first; i <= last; i += range.step) indices.push_back(i);
  return indices;
}

cv::Mat FrameDescriptors(const TumDataset& dataset, int index, const Config& config) {
  return ExtractFeatures(dataset.LoadFrame(index), config.features, config.depth_noise).descriptors;
}

}  // namespace tools
}  // namespace dslam
