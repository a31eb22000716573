// Odometry's re-anchoring step (reanchoring.h): after a weak episode, the tracked pose checked
// against the verified points made before it.
#include "dslam/features/features.h"
#include "dslam/tracking/odometry.h"
#include "dslam/tracking/pose_estimation.h"
#include "dslam/tracking/reanchoring.h"
#include "dslam/tracking/relocalisation.h"

namespace dslam {

void Odometry::ReanchorAfterWeakEpisode(Current* current, FrameResult* result) {
  const int frame_index = result->frame_index;
  if (!weak_episode_.Update(frame_index, current->pose.num_inliers, config_.tracking)) return;
  const int first_frame = weak_episode_.first_frame();
  const std::vector<PointId> older =
      VerifiedPointsMadeBefore(map_, first_frame - kReanchorMarginFrames);
  if (static_cast<int>(older.size()) < kReanchorMinPoints) {
    weak_episode_.End();  // nothing made before the episode to check against
    return;
  }
  const std::vector<PointMatch> matches =
      MatchByDescriptor(map_, older, current->features, DescriptorMatchRules());
  const uint32_t seed = static_cast<uint32_t>(frame_index) + 5u;  // Relocalise uses +2
  const PoseResult found =
      EstimateRobustPoseFromMatches(map_, matches, current->features, *current->frame->camera,
                                    PointSelection::kVerified, config_, seed);
  if (!found.success || found.num_inliers < kReanchorMinInliers ||
      found.num_inliers < kReanchorMinInlierShare * matches.size()) {
    return;  // checked again at the next strong frame, until kMaxCheckFrames
  }
  weak_episode_.End();
  // [world_old <- world_current]: the tracked pose onto the one the older map gives.
  MapCorrection correction;
  correction.first_frame = first_frame;
  correction.T_new_old = found.T_camera_world.inverse() * current->T_camera_world;
  if (!CorrectionWorthApplying(correction.T_new_old, config_.tracking)) return;
  correction.pivot_world = CorrectionPivot(map_, first_frame);
  correction.share = CorrectionShares(map_, first_frame, current->pose.information);
  map_.MoveMadeSince(correction);
  const Eigen::Isometry3d T_old_new = correction.T_new_old.inverse();
  current->T_camera_world = current->T_camera_world * T_old_new;
  current->pose.T_camera_world = current->T_camera_world;
  previous_.T_camera_world = previous_.T_camera_world * T_old_new;
  motion_.CorrectLastPose(correction.T_new_old * motion_.last_pose());
  result->T_world_previous_camera = correction.T_new_old * result->T_world_previous_camera;
  result->reanchored = correction;
}

}  // namespace dslam
