#include "dslam/tracking/front_end_static_points.h"

#include <algorithm>

namespace dslam {
namespace {

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
    const Eigen::Isometry3d& T_camera_world,
    const std::vector<const FrameMeasurements*>& reference_frames,
    const StaticPointsConfig& config) {
  FrontEndStaticPoints out;
  CorrelationInput input;
  input.T_camera_world.push_back(T_camera_world);  // frame 0: current
  for (const FrameMeasurements* frame : reference_frames) {
    input.T_camera_world.push_back(frame->T_camera_world);
  }
  for (size_t m = 0; m < matches.size(); ++m) {
    const MapPoint* point = map.Find(matches[m].id);
    const auto& measurement = features.features[matches[m].feature].measurement;
    if (point == nullptr || !measurement) continue;
    const int index = static_cast<int>(input.points_world.size());
    input.points_world.push_back(point->p_world);
    out.graph_match.push_back(static_cast<int>(m));
    AddObservation(index, 0, measurement->y_camera, measurement->covariance, &input);
    for (size_t k = 0; k < reference_frames.size(); ++k) {
      const auto found = reference_frames[k]->by_point.find(point->id);
      if (found == reference_frames[k]->by_point.end()) continue;
      AddObservation(index, static_cast<int>(k) + 1, found->second.y_camera,
                     found->second.covariance, &input);
    }
  }
  if (static_cast<int>(input.points_world.size()) < config.min_graph_points) return out;
  out.result = DetermineStaticPoints(input, config);
  out.ran = true;
  return out;
}

std::vector<bool> ApplyStaticLabels(const FrontEndStaticPoints& front_end,
                                    const std::vector<PointMatch>& matches, const LabelRules& rules,
                                    int frame_index, Map* map) {
  std::vector<bool> excluded(matches.size(), false);
  if (!front_end.ran || front_end.result.static_component < 0) return excluded;
  for (size_t g = 0; g < front_end.graph_match.size(); ++g) {
    const int m = front_end.graph_match[g];
    MapPoint* point = map->Find(matches[m].id);
    if (point == nullptr) continue;
    switch (front_end.result.labels[g]) {
      case PointLabel::kStatic:
        point->isolated_frames = 0;
        // Consistent with the static world again (e.g. wrongly unmarked, or stopped moving).
        // The longer a point was seen moving, the longer it must look static again (up to
        // remark_frames): a static point unmarked by one bad frame comes back at once.
        if (!point->marked &&
            ++point->static_streak >= std::min(rules.remark_frames, point->dynamic_frames)) {
          point->marked = true;
          point->dynamic_frames = 0;
        }
        if (point->marked && frame_index - point->created_frame >= rules.verify_frames) {
          point->candidate = false;
        }
        break;
      case PointLabel::kDynamic:
        point->marked = false;
        point->static_streak = 0;
        ++point->dynamic_frames;
        point->candidate = false;
        excluded[m] = true;
        break;
      case PointLabel::kIsolated:
        excluded[m] = true;
        point->static_streak = 0;
        if (++point->isolated_frames >= rules.isolated_frames_to_unmark) point->marked = false;
        break;
      case PointLabel::kUndecided:
      case PointLabel::kUnverified:
        break;
    }
  }
  return excluded;
}

}  // namespace dslam
