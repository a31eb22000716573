#pragma once
// Internal to dslam_core: the point-correlation measurements z_ijk of an edge list.

#include <vector>

#include <Eigen/Core>

#include "dslam/static_points/correlation_problem.h"

namespace dslam {
namespace internal {

/// z_ijk = y_ik - y_jk with information C_ijk^-1 = (C_ik + C_jk)^-1 (paper Eq. meas_con_imp).
struct CorrelationMeasurement {
  int edge = 0;                    ///< index into the edge list
  int frame = 0;                   ///< frame k
  Eigen::Vector3d z;               ///< [m] camera frame k
  Eigen::Matrix3d information;     ///< [1/m^2] C_ijk^-1, camera frame k
  Eigen::Matrix3d R_camera_world;  ///< rotation of frame k
  bool active = true;              ///< inlier (not culled)
  double chi2 = 0.0;               ///< [-] last squared Mahalanobis error
};

/// Every measurement of every edge: frames in which both endpoints are observed, in edge order
/// and increasing frame. Throws std::invalid_argument on out-of-range indices.
std::vector<CorrelationMeasurement> BuildMeasurements(const CorrelationInput& input,
                                                      const std::vector<GraphEdge>& edges);

}  // namespace internal
}  // namespace dslam
