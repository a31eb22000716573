#pragma once
// Re-anchoring after a weak episode. While people cover most of the view the pose rests on few
// static points and can turn away from the truth; the keyframes and points made meanwhile agree
// with the wrong pose, so the local map keeps it after the view clears
// (docs/benchmarks/tracking.md, issue 32 part 2: synthetic `walking` seeds 2-5 turn by 11-19 deg
// while walkers cover 80-93 % of the image). A weak episode begins at a tracked frame with fewer
// than tracking.reanchor_weak_inliers pose inliers. At a later frame with at least
// tracking.reanchor_strong_inliers (and kMinWeakFrames after the episode began), the frame is
// matched by descriptor against the verified static points made before the episode; a RANSAC pose
// over those matches (verified points only: people cannot vote) says where the older map puts
// the camera. When it differs from the tracked pose by at least reanchor_min_correction_m or
// reanchor_min_correction_deg, everything made since the episode began (keyframes, window and
// archive, and points) moves onto the older map (Map::MoveMadeSince): the current pose by the
// correction that takes it onto the pose the older map gives, each keyframe by a share of it that
// grows with the uncertainty of the poses up to it (CorrectionShares), so that an error which
// grew while the view was covered is taken back where it grew. An episode without an accepted check ends kMaxCheckFrames after it began.

#include <map>
#include <vector>

#include <Eigen/Geometry>

#include "dslam/core/tracking_config.h"
#include "dslam/tracking/map.h"

namespace dslam {

constexpr int kMinWeakFrames = 5;     ///< [frames] an episode is checked this long after it began
constexpr int kMaxCheckFrames = 150;  ///< [frames] after this long without a check, it ends
constexpr int kReanchorMarginFrames = 3;  ///< [frames] points made this soon before it are left out
constexpr int kReanchorMinPoints = 50;    ///< older verified points needed for a check
constexpr int kReanchorMinInliers = 40;   ///< RANSAC inliers of an accepted check
constexpr double kReanchorMinInlierShare = 0.3;  ///< [-] of the descriptor matches

/// The state of a weak episode over tracked frames.
class WeakEpisode {
 public:
  /// Feeds a tracked frame with `pose_inliers`. Returns true when this frame should be checked
  /// against the map made before the episode (first_frame()).
  bool Update(int frame_index, int pose_inliers, const TrackingConfig& config);
  /// Ends the episode (after a check that was accepted or decided nothing needs moving, after
  /// kMaxCheckFrames, or at a reset).
  void End() { first_frame_ = -1; }
  /// First frame of the current episode; -1 when there is none.
  int first_frame() const { return first_frame_; }

 private:
  int first_frame_ = -1;
};

/// The verified static points (marked, not candidates) created before frame `before_frame` and
/// observed by keyframes (window and archive) made before it: each once, oldest keyframe first.
std::vector<PointId> VerifiedPointsMadeBefore(const Map& map, int before_frame);

/// [rad^2] Variance of the rotation of a pose with 6x6 `information` (order [dtheta, dt], as
/// KeyFrame::information): the trace of the rotation block of its inverse; 0 when the
/// information is not positive definite (unknown, e.g. the first keyframe).
double RotationVariance(const Eigen::Matrix<double, 6, 6>& information);

/// Shares (MapCorrection::share) for the keyframes made from `first_frame` on, with the frame
/// that re-anchors (pose information `current_information`) taking all: the error of a chain of
/// poses grows with each pose's uncertainty, so keyframe k takes the sum of RotationVariance up
/// to and including it over the sum of all, the current frame's included (equal steps when all
/// are 0).
std::map<int, double> CorrectionShares(const Map& map, int first_frame,
                                       const Eigen::Matrix<double, 6, 6>& current_information);

/// [m] Where the episode began: the camera centre of the newest keyframe made before
/// `first_frame`; of the oldest made since when there is none.
Eigen::Vector3d CorrectionPivot(const Map& map, int first_frame);

/// Whether the correction `T_new_old` is large enough to apply (reanchor_min_correction_m or
/// reanchor_min_correction_deg reached).
bool CorrectionWorthApplying(const Eigen::Isometry3d& T_new_old, const TrackingConfig& config);

}  // namespace dslam
