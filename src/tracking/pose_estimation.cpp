#include "dslam/tracking/pose_estimation.h"

#include "dslam/core/geometry.h"
#include "dslam/tracking/robust_pose.h"

namespace dslam {
namespace {

// Observations of the selected matches and, per observation, its index in `matches`.
struct Observations {
  std::vector<PoseObservation> observations;
  std::vector<int> match_index;
};

Observations BuildObservations(const Map& map, const std::vector<PointMatch>& matches,
                               const FrameFeatures& features, const Eigen::Matrix3d& R_camera_world,
                               PointSelection selection, const std::vector<bool>& excluded,
                               double pixel_sigma_px) {
  Observations out;
  for (size_t m = 0; m < matches.size(); ++m) {
    const MapPoint* point = map.Find(matches[m].id);
    if (point == nullptr) continue;
    if (selection != PointSelection::kAll && !point->marked) continue;
    if (selection == PointSelection::kVerified && point->candidate) continue;
    if (!excluded.empty() && excluded[m]) continue;
    const Feature& feature = features.features[matches[m].feature];
    if (feature.measurement) {
      PointMeasurement measurement = *feature.measurement;
      measurement.covariance += RotatedCovariance(R_camera_world, point->cov_world);
      out.observations.push_back(PoseObservation::WithDepth(point->p_world, measurement));
    } else {
      const double sigma = pixel_sigma_px * features.octave_scale[feature.octave];
      out.observations.push_back(
          PoseObservation::PixelOnly(point->p_world, feature.uv_ideal, sigma));
    }
    out.match_index.push_back(static_cast<int>(m));
  }
  return out;
}

// Re-indexes the result's inliers from observations to matches.
PoseResult ToMatches(PoseResult result, const Observations& obs, size_t num_matches) {
  std::vector<bool> per_match(num_matches, false);
  for (size_t o = 0; o < result.inliers.size(); ++o) {
    if (result.inliers[o]) per_match[obs.match_index[o]] = true;
  }
  result.inliers = std::move(per_match);
  return result;
}

}  // namespace

PoseResult EstimatePoseFromMatches(const Map& map, const std::vector<PointMatch>& matches,
                                   const FrameFeatures& features, const PinholeCamera& camera,
                                   const Eigen::Isometry3d& T_camera_world_init,
                                   PointSelection selection, const std::vector<bool>& excluded,
                                   const Config& config) {
  const Observations obs =
      BuildObservations(map, matches, features, T_camera_world_init.rotation(), selection, excluded,
                        config.depth_noise.pixel_sigma_px);
  return ToMatches(EstimatePose(obs.observations, T_camera_world_init, camera, config.pose), obs,
                   matches.size());
}

PoseResult EstimateRobustPoseFromMatches(const Map& map, const std::vector<PointMatch>& matches,
                                         const FrameFeatures& features, const PinholeCamera& camera,
                                         PointSelection selection, const Config& config,
                                         uint32_t seed) {
  // The map covariance is rotated with an unknown pose here: leave it to RANSAC's extra sigma.
  const Observations obs = BuildObservations(map, matches, features, Eigen::Matrix3d::Zero(),
                                             selection, {}, config.depth_noise.pixel_sigma_px);
  return ToMatches(EstimatePoseRobust(obs.observations, camera, config.pose, seed), obs,
                   matches.size());
}

}  // namespace dslam
