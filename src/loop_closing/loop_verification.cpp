#include "dslam/loop_closing/loop_verification.h"

#include <unordered_set>

#include "dslam/features/matching.h"
#include "dslam/tracking/relocalisation.h"
#include "dslam/tracking/robust_pose.h"

namespace dslam {
namespace {

/// Verified static points with a descriptor listed by the keyframes `ids` and not by `query`,
/// each once, in the order of the ids and then of KeyFrame::points.
std::vector<PointId> MatchSidePoints(const Map& map, const KeyFrame& query,
                                     const std::vector<int>& ids) {
  std::unordered_set<PointId> seen(query.points.begin(), query.points.end());
  std::vector<PointId> out;
  for (int id : ids) {
    const KeyFrame* keyframe = map.FindKeyFrame(id);
    if (keyframe == nullptr) continue;
    for (PointId point_id : keyframe->points) {
      const MapPoint* point = map.Find(point_id);
      if (point == nullptr || !point->IsVerifiedStatic() || point->descriptor.empty()) continue;
      if (seen.insert(point_id).second) out.push_back(point_id);
    }
  }
  return out;
}

}  // namespace

std::vector<PointId> StaticMeasuredPoints(const Map& map, const KeyFrame& keyframe) {
  std::unordered_set<PointId> seen;
  std::vector<PointId> out;
  for (PointId id : keyframe.points) {
    const MapPoint* point = map.Find(id);
    if (point == nullptr || !point->IsVerifiedStatic() || point->descriptor.empty()) continue;
    if (keyframe.measurements.by_point.count(id) == 0) continue;
    if (seen.insert(id).second) out.push_back(id);
  }
  return out;
}

cv::Mat PointDescriptors(const Map& map, const std::vector<PointId>& points) {
  cv::Mat out;
  for (PointId id : points) out.push_back(map.Find(id)->descriptor);
  return out;
}

int ImageQuadrants(const std::vector<Eigen::Vector3d>& y_camera, const PinholeCamera& camera) {
  bool reached[4] = {false, false, false, false};
  for (const Eigen::Vector3d& y : y_camera) {
    if (y.z() <= 0.0) continue;
    const Eigen::Vector2d uv = camera.Project(y);
    const int right = uv.x() >= 0.5 * camera.width() ? 1 : 0;
    const int lower = uv.y() >= 0.5 * camera.height() ? 1 : 0;
    reached[2 * lower + right] = true;
  }
  return reached[0] + reached[1] + reached[2] + reached[3];
}

LoopVerification VerifyLoop(const Map& map, const KeyFrame& query,
                            const std::vector<int>& match_side, const PinholeCamera& camera,
                            const LoopClosingConfig& config, const PoseConfig& pose_config,
                            std::uint32_t seed) {
  const std::vector<PointId> query_points = StaticMeasuredPoints(map, query);
  const std::vector<PointId> train_points = MatchSidePoints(map, query, match_side);
  LoopVerification out;
  if (query_points.empty() || train_points.empty()) return out;
  const DescriptorMatchRules rules;  // relocalisation's: the same acceptance of a match
  const std::vector<DescriptorMatch> matches =
      MatchBruteForce(PointDescriptors(map, query_points), PointDescriptors(map, train_points),
                      rules.max_distance_bits, rules.ratio);
  std::vector<PoseObservation> observations;
  for (const DescriptorMatch& m : matches) {
    observations.push_back(
        PoseObservation::WithDepth(map.Find(train_points[m.train])->p_world,
                                   query.measurements.by_point.at(query_points[m.query])));
  }
  out.matches = static_cast<int>(matches.size());
  const PoseResult pose = EstimatePoseRobust(observations, camera, pose_config, seed);
  if (!pose.success) return out;
  out.T_world_query = pose.T_camera_world.inverse();
  std::vector<Eigen::Vector3d> inlier_y;
  for (size_t i = 0; i < observations.size(); ++i) {
    if (pose.inliers[i]) inlier_y.push_back(observations[i].y_camera);
  }
  out.inliers = static_cast<int>(inlier_y.size());
  out.quadrants = ImageQuadrants(inlier_y, camera);
  out.accepted = out.inliers >= config.min_inliers &&
                 out.inliers >= config.min_inlier_share * out.matches &&
                 out.quadrants >= config.min_image_quadrants;
  return out;
}

}  // namespace dslam
