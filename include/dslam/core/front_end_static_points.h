#pragma once
// Front-end static point determination (paper Sec. V-A "Determination of Static Points by the
// Front End"): after the initial pose, the tracked marked points with depth form a Delaunay
// graph whose edges are checked against point-correlation measurements of two frames; points
// outside the largest-volume component lose their mark.
//
// Which two frames: the paper compares the previous frame with the current one. At 30 Hz that
// baseline is too short to see walking people (the edge changes are the size of the depth noise,
// field notes), so by default ("reference") the first frame is each point's reference keyframe
// observation, held as the map point position p_world with its covariance (a pseudo-frame with
// T_camera_world = identity): the baseline is then the time since the point was created, up to
// the keyframe window. "previous" is the paper's choice and "both" uses all three.

#include <string>
#include <unordered_map>
#include <vector>

#include "dslam/core/config.h"
#include "dslam/core/depth_uncertainty.h"
#include "dslam/core/local_map_matching.h"
#include "dslam/core/static_points.h"

namespace dslam {

/// Measurements of one frame that the next frame's front end can compare with.
struct FrameMeasurements {
  Eigen::Isometry3d T_camera_world = Eigen::Isometry3d::Identity();
  std::unordered_map<PointId, PointMeasurement> by_point;  ///< y and C per matched point
};

/// Output of the front end: the determination's result and which matches it covered.
struct FrontEndStaticPoints {
  StaticPointsResult result;
  std::vector<int> graph_match;  ///< per graph point: index into the frame's matches
  bool ran = false;              ///< false when too few points had the needed measurements
};

/// Builds the problem from the marked matched points with a depth measurement (and, for
/// "previous"/"both", a measurement in `previous`), runs DetermineStaticPoints and returns the
/// result. `reference` is "reference", "previous" or "both" (TrackingConfig).
FrontEndStaticPoints DetermineStaticPointsFrontEnd(
    const Map& map, const std::vector<PointMatch>& matches, const FrameFeatures& features,
    const Eigen::Isometry3d& T_camera_world, const FrameMeasurements& previous,
    const std::string& reference, const StaticPointsConfig& config);

/// Unmarks the points labelled dynamic or isolated (their correlations were all inconsistent).
/// Returns the number of points unmarked. Nothing changes when no static component was chosen.
int ApplyStaticLabels(const FrontEndStaticPoints& front_end,
                      const std::vector<PointMatch>& matches, Map* map);

}  // namespace dslam
