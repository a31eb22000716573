#include "dslam/core/front_end_static_points.h"

namespace dslam {
namespace {

constexpr int kMinGraphPoints = 8;  // fewer: no meaningful Delaunay graph

void AddObservation(int point, int frame, const Eigen::Vector3d& y, const Eigen::Matrix3d& C,
                    CorrelationInput* input) {
  PointObservation obs;
  obs.point = point;
  obs.frame = frame;
  obs.y_camera = y;
  obs.covariance = C;
  input->observations.push_back(obs);
}

}  // namespace

FrontEndStaticPoints DetermineStaticPointsFrontEnd(
    const Map& map, const std::vector<PointMatch>& matches, const FrameFeatures& features,
    const Eigen::Isometry3d& T_camera_world, const FrameMeasurements& previous,
    const std::string& reference, const StaticPointsConfig& config) {
  const bool use_map = reference != "previous";
  const bool use_previous = reference != "reference";
  FrontEndStaticPoints out;
  CorrelationInput input;
  // Frame 0: current. Frame 1: the map pseudo-frame (identity). Frame 2: previous frame.
  input.T_camera_world = {T_camera_world, Eigen::Isometry3d::Identity(),
                          previous.T_camera_world};
  for (size_t m = 0; m < matches.size(); ++m) {
    const MapPoint* point = map.Find(matches[m].id);
    const auto& measurement = features.features[matches[m].feature].measurement;
    if (point == nullptr || !point->marked || !measurement) continue;
    const auto prev = previous.by_point.find(point->id);
    if (use_previous && !use_map && prev == previous.by_point.end()) continue;
    const int index = static_cast<int>(input.points_world.size());
    input.points_world.push_back(point->p_world);
    out.graph_match.push_back(static_cast<int>(m));
    AddObservation(index, 0, measurement->y_camera, measurement->covariance, &input);
    if (use_map) AddObservation(index, 1, point->p_world, point->cov_world, &input);
    if (use_previous && prev != previous.by_point.end()) {
      AddObservation(index, 2, prev->second.y_camera, prev->second.covariance, &input);
    }
  }
  if (static_cast<int>(input.points_world.size()) < kMinGraphPoints) return out;
  out.result = DetermineStaticPoints(input, config);
  out.ran = true;
  return out;
}

int ApplyStaticLabels(const FrontEndStaticPoints& front_end,
                      const std::vector<PointMatch>& matches, Map* map) {
  if (!front_end.ran || front_end.result.static_component < 0) return 0;
  int unmarked = 0;
  for (size_t g = 0; g < front_end.graph_match.size(); ++g) {
    const PointLabel label = front_end.result.labels[g];
    if (label != PointLabel::kDynamic && label != PointLabel::kIsolated) continue;
    MapPoint* point = map->Find(matches[front_end.graph_match[g]].id);
    if (point != nullptr && point->marked) {
      point->marked = false;
      ++unmarked;
    }
  }
  return unmarked;
}

}  // namespace dslam
