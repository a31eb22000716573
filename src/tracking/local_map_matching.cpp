#include "dslam/tracking/local_map_matching.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace dslam {
namespace {

// Pyramid level at which a point seen at `distance_m` should appear: its creation level shifted
// by the change of apparent size (ORB-SLAM2's PredictScale); -1 when unknown.
// `log_scale` is log(scales[1]).
int PredictOctave(const MapPoint& point, double distance_m, const std::vector<double>& scales,
                  double log_scale) {
  if (point.reference_distance_m <= 0.0 || scales.size() < 2) return -1;
  const double shift = std::log(point.reference_distance_m / distance_m) / log_scale;
  const int octave = point.octave + static_cast<int>(std::lround(shift));
  return std::clamp(octave, 0, static_cast<int>(scales.size()) - 1);
}

// The measurement of `point` (id `id`) in search.last_frame when it is marked and was measured
// there, else nullptr.
const PointMeasurement* LastMeasurement(const LocalMapSearch& search, PointId id,
                                        const MapPoint& point) {
  if (search.last_frame == nullptr || !point.marked) return nullptr;
  const auto found = search.last_frame->by_point.find(id);
  return found == search.last_frame->by_point.end() ? nullptr : &found->second;
}

}  // namespace

ProjectedLocalMap ProjectLocalMap(const Map& map, const std::vector<PointId>& candidates,
                                  const FrameFeatures& features, const PinholeCamera& camera,
                                  const Eigen::Isometry3d& T_camera_world,
                                  const LocalMapSearch& search) {
  ProjectedLocalMap projected;
  projected.points.reserve(candidates.size());
  projected.ids.reserve(candidates.size());
  const std::vector<double>& scales = features.octave_scale;
  const double log_scale = scales.size() < 2 ? 0.0 : std::log(scales[1]);
  const Eigen::Isometry3d T_camera_last =
      search.last_frame == nullptr ? Eigen::Isometry3d::Identity()
                                   : T_camera_world * search.last_frame->T_camera_world.inverse();
  for (PointId id : candidates) {
    const MapPoint* point = map.Find(id);
    if (point == nullptr) continue;
    const PointMeasurement* last = LastMeasurement(search, id, *point);
    const Eigen::Vector3d p_camera =
        last != nullptr ? T_camera_last * last->y_camera : T_camera_world * point->p_world;
    if (p_camera.z() < search.min_depth_m) continue;
    const Eigen::Vector2d uv = camera.Project(p_camera);
    if (!camera.InImage(uv)) continue;
    ProjectedPoint candidate;
    candidate.uv_ideal = uv;
    candidate.descriptor = point->descriptor;
    candidate.predicted_octave = PredictOctave(*point, p_camera.norm(), scales, log_scale);
    candidate.radius_px = search.radius_px;
    projected.points.push_back(std::move(candidate));
    projected.ids.push_back(id);
  }
  return projected;
}

std::vector<PointMatch> ClaimLocalMapMatches(const ProjectedLocalMap& projected,
                                             const FrameFeatures& features,
                                             std::vector<bool>* feature_taken) {
  const std::vector<int> found = SearchByProjection(projected.points, features);
  std::vector<PointMatch> matches;
  for (size_t k = 0; k < found.size(); ++k) {
    const int f = found[k];
    if (f < 0 || (*feature_taken)[f]) continue;
    (*feature_taken)[f] = true;
    matches.push_back({projected.ids[k], f});
  }
  return matches;
}

std::vector<PointMatch> MatchLocalMap(Map* map, const std::vector<PointId>& candidates,
                                      const FrameFeatures& features, const PinholeCamera& camera,
                                      const Eigen::Isometry3d& T_camera_world,
                                      const LocalMapSearch& search,
                                      std::vector<bool>* feature_taken) {
  const ProjectedLocalMap projected =
      ProjectLocalMap(*map, candidates, features, camera, T_camera_world, search);
  if (search.count_visible) {
    for (PointId id : projected.ids) {
      MapPoint* point = map->FindWritable(id);  // a frozen point's count stays as it was
      if (point != nullptr) ++point->times_visible;
    }
  }
  return ClaimLocalMapMatches(projected, features, feature_taken);
}

}  // namespace dslam
