#include "dslam/mapping/region_join.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "cell_grid.h"

namespace dslam {
namespace {

/// [first, last] cell columns of each label of `labels` (index label - 1); first > last when the
/// label has no cell.
std::vector<std::pair<int, int>> ColumnRanges(const cv::Mat& labels, size_t regions) {
  std::vector<std::pair<int, int>> ranges(regions, {labels.cols, -1});
  for (int r = 0; r < labels.rows; ++r) {
    const uint16_t* row = labels.ptr<uint16_t>(r);
    for (int c = 0; c < labels.cols; ++c) {
      if (row[c] == 0 || row[c] > regions) continue;
      auto& range = ranges[row[c] - 1];
      range.first = std::min(range.first, c);
      range.second = std::max(range.second, c);
    }
  }
  return ranges;
}

/// Overlap of two column ranges as a share of the narrower one (0 when either is empty).
double Overlap(const std::pair<int, int>& a, const std::pair<int, int>& b) {
  const int narrower = std::min(a.second - a.first, b.second - b.first) + 1;
  if (narrower <= 0) return 0.0;
  const int common = std::min(a.second, b.second) - std::max(a.first, b.first) + 1;
  return std::max(common, 0) / static_cast<double>(narrower);
}

/// [m] largest gap between the world boxes of two regions along one axis (0 when they overlap).
double BoxGap(const DynamicRegion& a, const DynamicRegion& b) {
  const Eigen::Vector3d gap = (a.min_world - b.max_world).cwiseMax(b.min_world - a.max_world);
  return std::max(gap.maxCoeff(), 0.0);
}

/// Removes region `index` (already merged) and relabels the later regions one down.
void RemoveRegion(size_t index, DynamicMask* mask) {
  mask->regions.erase(mask->regions.begin() + static_cast<std::ptrdiff_t>(index));
  for (size_t k = index; k < mask->regions.size(); ++k) {
    const uint16_t label = static_cast<uint16_t>(k + 1);
    mask->labels.setTo(label, mask->labels == mask->regions[k].label);
    mask->regions[k].label = label;
  }
}

}  // namespace

int JoinStackedRegions(const DynamicMaskConfig& mask_config, const ObjectsConfig& objects_config,
                       DynamicMask* mask) {
  int joins = 0;
  for (bool joined = true; joined;) {
    joined = false;
    const std::vector<std::pair<int, int>> columns =
        ColumnRanges(mask->labels, mask->regions.size());
    for (size_t a = 0; a < mask->regions.size() && !joined; ++a) {
      for (size_t b = a + 1; b < mask->regions.size() && !joined; ++b) {
        if (Overlap(columns[a], columns[b]) <= objects_config.split_max_overlap) continue;
        if (BoxGap(mask->regions[a], mask->regions[b]) > mask_config.margin_m) continue;
        MergeRegion(mask->regions[b], &mask->regions[a], &mask->labels);
        RemoveRegion(b, mask);
        joined = true;
        ++joins;
      }
    }
  }
  return joins;
}

}  // namespace dslam
