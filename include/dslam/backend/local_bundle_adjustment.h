#pragma once
// Local bundle adjustment (paper Sec. V, back end): the poses of the window's keyframes and the
// positions of the verified static points they measure, from every RGB-D measurement of those
// points in those keyframes (paper Eq. rgbd_yik: y_ik = R_k p_i + t_k + n, n ~ N(0, C_ik)).
//
// Only verified static points (marked, not candidates) measured in at least 2 keyframes enter.
// The oldest `backend.ba_fixed_keyframes` keyframes, and keyframes with fewer than 10 such points,
// keep their poses; frozen keyframes and points (Map::Freeze: a loaded map used for localisation
// only) are constants of the problem and are not written back. Two rounds of at most 10 iterations,
// as in ORB-SLAM2's LocalBundleAdjustment: Levenberg-Marquardt robust by the Huber width
// `pose.huber_delta_depth` (the motion-only BA's), then the measurements whose squared Mahalanobis
// error exceeds `pose.chi2_depth` are left out and the rest are optimised again. Fewer than 2
// window keyframes: nothing runs. Measurements stay in their keyframes: static point determination
// compares them. Points measured in the window but not optimised move with the newest keyframe that
// measured them.
//
// Safeguards against points that are marked but move (a person who stood still long enough to
// be verified): measurements inconsistent with the front end's poses and map (chi-square with
// the map point's covariance added) are left out from the start, and a solution that moves a
// keyframe further than its own frame's measurements allow (`ba_max_correction_chi2` under the
// front end's pose information) or than `ba_max_correction_m` / `ba_max_correction_deg` is not
// applied: with a person filling most of the window, the window could follow the person.

#include "dslam/core/config.h"
#include "dslam/tracking/backend_status.h"
#include "dslam/tracking/map.h"

namespace dslam {

/// Optimises the keyframe window of `map` in place (keyframe poses, their measurements' poses and
/// point positions) with config.backend and config.pose's 3-dof widths; see the top of this file.
/// Deterministic (one solver thread).
/// Returns what it did (LocalBaStats, tracking/backend_status.h).
LocalBaStats LocalBundleAdjustment(const Config& config, Map* map);

}  // namespace dslam
