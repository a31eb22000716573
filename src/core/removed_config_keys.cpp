#include "dslam/core/removed_config_keys.h"

#include <iterator>

namespace dslam {
namespace {

// One removed parameter per entry: section, name, why it went. A losing option names the
// BENCHMARKS.md section that measured it; a key that no measurement changed names the constant of
// the code that replaced it.
constexpr RemovedConfigKey kRemovedKeys[] = {
    {"depth_noise", "min_valid_window_pixels",
     "no measurement changed it; now 5 (MixDepth)"},
    {"features", "cell_size_px",
     "no measurement changed it; now 30 px (orb_pyramid.cpp)"},
    {"pose", "solver",
     "the Levenberg-Marquardt solver always runs; Ceres gave the same trajectories, slower "
     "(docs/benchmarks/tracking.md, \"Motion-only BA solver\"), and stays the tests' reference"},
    {"pose", "ransac_max_iterations",
     "no measurement changed it; now kRansacMaxHypotheses 300"},
    {"pose", "ransac_confidence",
     "no measurement changed it; now kRansacConfidence 0.999"},
    {"pose", "ransac_extra_sigma_m",
     "no measurement changed it; now kRansacExtraSigmaM 0.01 m"},
    {"static_points", "max_rounds",
     "no measurement changed it; now 4 (CullingOptions)"},
    {"static_points", "prior_sigma_m",
     "no measurement changed it; now 1 m (CullingOptions)"},
    {"static_points", "min_graph_points",
     "no measurement changed it; now kMinGraphPoints 8"},
    {"static_points", "min_component_points",
     "no measurement changed it; now 4 (StaticSelectionOptions)"},
    {"tracking", "unmarked_search_radius_px",
     "tried, off: docs/benchmarks/mapping.md, \"Unmarked points searched wider\""},
    {"tracking", "unmarked_max_offset_m",
     "tried, off: docs/benchmarks/mapping.md, \"Unmarked points searched wider\""},
    {"tracking", "search_min_depth_m",
     "no measurement changed it; now 0.1 m (odometry_steps.cpp)"},
    {"tracking", "init_min_points_factor",
     "no measurement changed it; now 2 (odometry.cpp)"},
    {"tracking", "front_end_reference",
     "the keyframes always: previous (the paper's) and both lost on every sequence with people "
     "(BENCHMARKS.md, \"Issue 50: switches no measurement chose\")"},
    {"tracking", "fuse_static_points",
     "tried, off: docs/benchmarks/tracking.md, \"Issue 46, part 4\" (better where nothing "
     "moves, worse on Bonn crowd 300-599, TUM rpy and walking)"},
    {"tracking", "descriptor_observations",
     "tried, off: docs/benchmarks/tracking.md, \"Map point descriptors refined from their "
     "observations\""},
    {"tracking", "cull_min_visible",
     "no measurement changed it; now 8 (odometry_keyframes.cpp)"},
    {"tracking", "robust_pose_points",
     "the marked matches always vote first, then all: `all` gave the same trajectories, "
     "`marked` lost frames (docs/benchmarks/backend.md, \"Back end, part 1\")"},
    {"tracking", "relocalisation_max_distance_bits",
     "no measurement changed it; now 64 (DescriptorMatchRules)"},
    {"tracking", "relocalisation_ratio",
     "no measurement changed it; now 0.8 (DescriptorMatchRules)"},
    {"backend", "spd_unmark_isolated",
     "it changed nothing: an isolated point is a component of one point, below "
     "spd_min_dynamic_points, so it keeps its mark either way (docs/benchmarks/tracking.md, "
     "\"Issue 46, part 4\")"},
    {"backend", "spd_enabled",
     "always on with static_points.enabled: local BA alone lost (`git show "
     "0da3eda:BENCHMARKS.md`, \"Back end, part 2\")"},
    {"backend", "spd_min_covisible_points",
     "no measurement changed it; now 20 (window_static_points.cpp)"},
    {"backend", "ba_min_keyframes",
     "no measurement changed it; now 2"},
    {"backend", "ba_min_point_keyframes",
     "now 2: 3 was tried and not adopted (docs/benchmarks/backend.md, \"Back end on or off, "
     "seeds 1-5\")"},
    {"backend", "ba_min_keyframe_points",
     "no measurement changed it; now 10"},
    {"backend", "ba_max_iterations",
     "no measurement changed it; now 10"},
    {"backend", "ba_huber_delta",
     "merged into pose.huber_delta_depth"},
    {"backend", "ba_chi2",
     "merged into pose.chi2_depth"},
    {"dynamic_mask", "depth_change_seeds",
     "always on: docs/benchmarks/mapping.md, \"Depth-change seeds of the dynamic mask\""},
    {"dynamic_mask", "depth_change_stride",
     "no measurement changed it; now kDepthChangeStride 2"},
    {"objects", "min_cells",
     "no measurement changed it; now 20 (object_tracker.cpp)"},
    {"objects", "min_velocity_points",
     "no measurement changed it; now 3 (object_tracker.cpp)"},
    {"objects", "split_min_points",
     "no measurement changed it; now kSplitMinPoints 5"},
    {"objects", "carry_points",
     "always on: docs/benchmarks/mapping.md, \"Lost points carried by optical flow, stacked "
     "regions joined\""},
    {"objects", "join_stacked_regions",
     "always on: docs/benchmarks/mapping.md, \"Lost points carried by optical flow, stacked "
     "regions joined\""},
    {"objects", "carry_window_px",
     "no measurement changed it; now PointCarrier::kWindowPx 11"},
    {"objects", "carry_levels",
     "no measurement changed it; now PointCarrier::kLevels 3"},
    {"objects", "carry_max_error_px",
     "no measurement changed it; now PointCarrier::kMaxErrorPx 0.5 px"},
    {"objects", "carry_max_points",
     "no measurement changed it; now PointCarrier::kMaxPoints 500"},
    {"map", "max_depth_m",
     "merged into depth_noise.max_depth_m"},
    {"map", "free_space_min_misses",
     "no measurement changed it; now 1 (FreeSpaceTolerance)"},
};

}  // namespace

RemovedConfigKeyList RemovedConfigKeys() {
  return RemovedConfigKeyList(kRemovedKeys, std::size(kRemovedKeys));
}

const RemovedConfigKey* FindRemovedConfigKey(std::string_view section, std::string_view name) {
  for (const RemovedConfigKey& key : RemovedConfigKeys()) {
    if (section == key.section && name == key.name) return &key;
  }
  return nullptr;
}

std::string RemovedConfigKeyWarning(const std::string& shown, const RemovedConfigKey& key) {
  return shown + " was removed (" + std::string(key.reason) + "); its value is ignored";
}

}  // namespace dslam
