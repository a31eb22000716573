#include "dslam/tracking/map_point_creation.h"

#include <algorithm>

namespace dslam {

std::vector<int> DynamicNeighbourhood(const FrameFeatures& features,
                                      const std::vector<PointMatch>& matches, const Map& map,
                                      double radius_px) {
  struct Neighbour {
    Eigen::Vector2d uv;
    bool marked;
    int dynamic_frames;
  };
  std::vector<Neighbour> neighbours;
  for (const PointMatch& match : matches) {
    const MapPoint* point = map.Find(match.id);
    if (point) {
      neighbours.push_back(
          {features.features[match.feature].uv_ideal, point->marked, point->dynamic_frames});
    }
  }
  const double r2 = radius_px * radius_px;
  std::vector<int> inherited(features.features.size(), -1);
  std::vector<int> unmarked_frames;
  for (size_t f = 0; f < features.features.size(); ++f) {
    int marked = 0;
    unmarked_frames.clear();
    for (const Neighbour& n : neighbours) {
      if ((n.uv - features.features[f].uv_ideal).squaredNorm() > r2) continue;
      if (n.marked) {
        ++marked;
      } else {
        unmarked_frames.push_back(n.dynamic_frames);
      }
    }
    if (static_cast<int>(unmarked_frames.size()) <= marked) continue;
    auto mid = unmarked_frames.begin() + unmarked_frames.size() / 2;
    std::nth_element(unmarked_frames.begin(), mid, unmarked_frames.end());
    inherited[f] = *mid;
  }
  return inherited;
}

std::vector<PointId> CreateMapPoints(const FrameFeatures& features,
                                     const std::vector<bool>& feature_taken,
                                     const std::vector<int>& dynamic_neighbourhood,
                                     const CreationContext& context, const TrackingConfig& config,
                                     Map* map) {
  std::vector<int> candidates;
  for (size_t f = 0; f < features.features.size(); ++f) {
    if (!feature_taken[f] && features.features[f].measurement) candidates.push_back(f);
  }
  std::sort(candidates.begin(), candidates.end(), [&](int a, int b) {
    return features.features[a].measurement->y_camera.z() <
           features.features[b].measurement->y_camera.z();
  });
  if (static_cast<int>(candidates.size()) > config.max_new_points) {
    candidates.resize(config.max_new_points);
  }
  std::vector<PointId> ids;
  for (int f : candidates) {
    const Feature& feature = features.features[f];
    MapPoint point;
    const PointMeasurement in_world = Transformed(*feature.measurement, context.T_world_camera);
    point.p_world = in_world.y_camera;
    point.cov_world = in_world.covariance;
    point.descriptor = features.descriptors.row(f).clone();
    point.octave = feature.octave;
    point.created_feature = f;
    point.reference_distance_m = feature.measurement->y_camera.norm();
    point.marked = dynamic_neighbourhood[f] < 0;
    point.dynamic_frames = std::max(0, dynamic_neighbourhood[f]);
    point.candidate = point.marked && context.new_points_are_candidates;
    point.created_frame = point.last_seen_frame = context.frame_index;
    point.times_visible = point.times_found = 1;
    ids.push_back(map->AddPoint(std::move(point)));
  }
  return ids;
}

}  // namespace dslam
