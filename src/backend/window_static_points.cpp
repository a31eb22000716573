#include "dslam/backend/window_static_points.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "dslam/core/stopwatch.h"
#include "dslam/static_points/static_points.h"

namespace dslam {
namespace {

// Window keyframes sharing fewer measured points with the newest keyframe are left out.
constexpr int kMinCovisiblePoints = 20;

// Indices of the window keyframes sharing at least `min_shared` measured points with the newest
// keyframe (the newest included), oldest first: the paper's "keyframes that have covisibility
// with the currently added keyframe".
std::vector<int> CovisibleKeyFrames(const Map& map, int min_shared) {
  const auto& keyframes = map.window();
  const FrameMeasurements& newest = keyframes.back().measurements;
  std::vector<int> covisible;
  for (size_t k = 0; k < keyframes.size(); ++k) {
    int shared = 0;
    for (const auto& entry : keyframes[k].measurements.by_point) {
      shared += newest.by_point.count(entry.first) > 0;
    }
    if (shared >= min_shared || k + 1 == keyframes.size()) covisible.push_back(static_cast<int>(k));
  }
  return covisible;
}

// The problem of Algorithm 1: the marked points measured in at least two of `keyframes` (in
// increasing id order), all their measurements there, and those keyframes' poses.
CorrelationInput CollectProblem(const Map& map, const std::vector<int>& keyframes,
                                double rotation_variance, std::vector<PointId>* ids) {
  std::unordered_map<PointId, int> measured_in;
  for (int k : keyframes) {
    for (const auto& entry : map.window()[k].measurements.by_point) {
      const MapPoint* point = map.Find(entry.first);
      if (point != nullptr && point->marked) ++measured_in[entry.first];
    }
  }
  ids->clear();
  for (const auto& [id, count] : measured_in) {
    if (count >= 2) ids->push_back(id);
  }
  std::sort(ids->begin(), ids->end());
  std::unordered_map<PointId, int> index_of;
  CorrelationInput input;
  for (PointId id : *ids) {
    index_of.emplace(id, static_cast<int>(input.points_world.size()));
    input.points_world.push_back(map.Find(id)->p_world);
  }
  for (size_t f = 0; f < keyframes.size(); ++f) {
    const FrameMeasurements& frame = map.window()[keyframes[f]].measurements;
    input.T_camera_world.push_back(frame.T_camera_world);
    input.rotation_covariance.push_back(rotation_variance * Eigen::Matrix3d::Identity());
    for (PointId id : *ids) {  // increasing id: the same order in every run
      const auto found = frame.by_point.find(id);
      if (found == frame.by_point.end()) continue;
      PointObservation observation;
      observation.point = index_of.at(id);
      observation.frame = static_cast<int>(f);
      observation.y_camera = found->second.y_camera;
      observation.covariance = found->second.covariance;
      input.observations.push_back(observation);
    }
  }
  return input;
}

// Points labelled dynamic may lose their marks; isolated points (every edge inconsistent) keep
// theirs: each is a component of its own, below backend.spd_min_dynamic_points.
bool LosesMark(PointLabel label) { return label == PointLabel::kDynamic; }

// Per component of `result`: whether its points labelled moving lose their marks. Algorithm 1
// unmarks every component but the static one; two departures (docs/benchmarks/backend.md, "Issue
// 32, part 6"):
// - A component of fewer than backend.spd_min_dynamic_points points keeps its marks: over a
//   window of up to 12 keyframes one bad measurement (blur, a depth edge) cuts a few points off,
//   while a moving body is cut off with many (on TUM rpy, where nothing moves, mostly 2-4).
// - When a component that would lose its marks holds more points than the static one, nothing
//   is unmarked: the window holds two "static worlds" (a person who filled the view and was
//   tracked as background, then the background again) and its volume rule would overrule
//   the front end's frame-by-frame decisions wholesale.
std::vector<bool> ComponentsLosingMarks(const StaticPointsResult& result,
                                        const BackendConfig& config) {
  std::vector<int> size(ComponentCount(result.component), 0);
  for (int c : result.component) ++size[c];
  std::vector<bool> loses(size.size(), false);
  if (result.static_component < 0) return loses;
  const int static_size = size[result.static_component];
  for (size_t i = 0; i < result.labels.size(); ++i) {
    const int c = result.component[i];
    if (!LosesMark(result.labels[i])) continue;
    if (size[c] > static_size) return std::vector<bool>(size.size(), false);
    loses[c] = size[c] >= config.spd_min_dynamic_points;
  }
  return loses;
}

}  // namespace

WindowStaticPointsStats DetermineStaticPointsInWindow(const Config& config, Map* map) {
  WindowStaticPointsStats stats;
  const Stopwatch total;
  if (map->window().size() < 2) return stats;
  const std::vector<int> keyframes = CovisibleKeyFrames(*map, kMinCovisiblePoints);
  if (keyframes.size() < 2) return stats;
  std::vector<PointId> ids;
  const double rotation_sigma = config.backend.spd_rotation_sigma_deg * M_PI / 180.0;
  const CorrelationInput input =
      CollectProblem(*map, keyframes, rotation_sigma * rotation_sigma, &ids);
  if (static_cast<int>(ids.size()) < kMinGraphPoints) return stats;
  const StaticPointsResult result = DetermineStaticPoints(input, config.static_points);
  const std::vector<bool> loses = ComponentsLosingMarks(result, config.backend);
  if (result.static_component >= 0) {
    for (size_t i = 0; i < ids.size(); ++i) {
      if (!loses[result.component[i]]) continue;
      if (!LosesMark(result.labels[i])) continue;
      MapPoint* point = map->FindWritable(ids[i]);
      if (point == nullptr) continue;  // frozen (a loaded map used for localisation only)
      // It stops driving motion estimation; the front end marks it again only after
      // tracking.remark_frames consecutive frames in which it looks static.
      point->Unmark(config.tracking.remark_frames);
      ++stats.unmarked;
    }
  }
  stats.ran = true;
  stats.keyframes = static_cast<int>(keyframes.size());
  stats.graph = result.stats;
  stats.total_ms = total.ElapsedMs();
  return stats;
}

}  // namespace dslam
