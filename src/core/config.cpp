#include "dslam/core/config.h"

#include <algorithm>
#include <cmath>

namespace dslam {

void BoundsChecker::operator()(const FieldInfo& info, const std::string& value) const {
  if (info.choices.empty()) return;
  if (std::find(info.choices.begin(), info.choices.end(), value) != info.choices.end()) return;
  std::string allowed;
  for (const auto& c : info.choices) allowed += (allowed.empty() ? "" : "|") + c;
  throw ConfigError(Name(info) + " = '" + value + "' is not one of " + allowed);
}

void Config::Validate() const {
  Sections(*this, [](const char* section, const auto& s) {
    using Section = std::decay_t<decltype(s)>;
    Section::Fields(s, BoundsChecker(std::string(section) + "."));
  });
  if (depth_noise.min_depth_m >= depth_noise.max_depth_m) {
    throw ConfigError("depth_noise.min_depth_m must be smaller than depth_noise.max_depth_m");
  }
  if (tracking.wide_search_radius_px < tracking.search_radius_px) {
    throw ConfigError(
        "tracking.wide_search_radius_px must not be smaller than "
        "tracking.search_radius_px");
  }
  if (tracking.reanchor_strong_inliers < tracking.reanchor_weak_inliers) {
    throw ConfigError(
        "tracking.reanchor_strong_inliers must not be smaller than "
        "tracking.reanchor_weak_inliers");
  }
  if (features.fast_threshold_min > features.fast_threshold) {
    throw ConfigError("features.fast_threshold_min must not exceed features.fast_threshold");
  }
  if (map.extent_m < map.voxel_size_m) {
    throw ConfigError("map.extent_m must not be smaller than map.voxel_size_m");
  }
  if (grid.min_height_m >= grid.max_height_m) {
    throw ConfigError("grid.min_height_m must be smaller than grid.max_height_m");
  }
  if (std::hypot(grid.up_x, grid.up_y, grid.up_z) < 0.1) {
    throw ConfigError("grid.up_x, grid.up_y, grid.up_z: the up vector must not be (near) zero");
  }
}

}  // namespace dslam
