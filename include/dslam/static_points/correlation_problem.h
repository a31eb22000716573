#pragma once
// Step 2 of static point determination (paper Sec. IV-B and V-A): inconsistent edge culling with
// the RGB-D point-correlation measurement model.
//
// Measurement (paper Eq. meas_con_imp): z_ijk = y_ik - y_jk, covariance C_ijk = C_ik + C_jk,
// y_ik = point i measured in camera k [m]. With the camera poses held fixed, the model
// h_ijk = R_camera_world,k (p_i - p_j) is linear in the points (the camera translation cancels),
// so each culling round of J_p = 1/2 sum e^T C^-1 e (Eq. geo_prior) is ONE sparse linear
// least-squares solve (3x3 blocks per point, Eigen SimplicialLDLT on the 3N x 3N normal
// equations), not an iterative nonlinear optimisation.
//
// Deviations from Algorithm 1, and why (measured in docs/readme/spd.md):
// - Anchoring: J_p is invariant to translating a connected component, so the normal equations
//   are singular. A weak isotropic prior (sigma = prior_sigma_m, default 1 m, i.e. ~1e-4 of the
//   information of a centimetre-level correlation) pulls every point to its initial estimate.
// - No Huber in the first round, and one-way culling (a dropped measurement stays dropped). Taken
//   literally (Huber from the start, measurements allowed back in) the two-frame problem settles
//   on one frame's layout and every inconsistent edge keeps one good-looking measurement.
// - Edge rule: an edge is inconsistent when fewer than min_inlier_fraction of its measurements
//   are inliers after the last round (always when none is). Default 1.0: every measurement must
//   stay an inlier. With 2 frames this equals the paper's "all outliers" (both residuals share
//   the discrepancy); with many frames the paper's rule lets an object in steady motion keep its
//   edges through the frames in the middle of the window (measured: 111/114 boundary edges cut
//   with 5 frames, 114/114 with the default). 0.0 reproduces Algorithm 1.

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/static_points/point_graph.h"

namespace dslam {

/// One measurement y_ik of map point `point` in frame `frame`.
struct PointObservation {
  int point = 0;                                         ///< index into points_world
  int frame = 0;                                         ///< index into T_camera_world
  Eigen::Vector3d y_camera = Eigen::Vector3d::Zero();    ///< [m] point in camera frame k
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< [m^2] of y_camera, camera frame k
};

/// The data of one static-point-determination problem.
struct CorrelationInput {
  std::vector<Eigen::Vector3d> points_world;      ///< [m] initial point estimates, world frame
  std::vector<Eigen::Isometry3d> T_camera_world;  ///< per frame: maps world points into camera k
  std::vector<PointObservation> observations;     ///< any order; at most one per (point, frame)
  /// [rad^2] per frame, or empty: covariance of a rotation error dtheta of frame k (left
  /// perturbation of T_camera_world). It adds [z]x Sigma [z]x^T to the covariance of each
  /// measurement z_ijk of that frame (z_ijk = R_k l_ij turns by dtheta; translation cancels).
  std::vector<Eigen::Matrix3d> rotation_covariance;
};

/// Parameters of the culling (mirrors StaticPointsConfig).
struct CullingOptions {
  int max_rounds = 4;                ///< [-] solve + cull rounds (stops early when stable)
  double chi2_threshold = 11.34;     ///< [-] 3-dof squared Mahalanobis error (99%)
  double prior_sigma_m = 1.0;        ///< [m] sigma of the anchoring prior per coordinate
  double min_inlier_fraction = 1.0;  ///< [-] an edge needs at least this share of inliers
};

/// Per-edge result of the culling; vectors are parallel to the edge list.
struct CullingResult {
  std::vector<bool> edge_kept;                ///< false: inconsistent edge, removed from the graph
  std::vector<int> edge_measurements;         ///< [-] frames in which both endpoints are observed
  std::vector<int> edge_inliers;              ///< [-] measurements still inliers at the end
  std::vector<double> edge_max_chi2;          ///< [-] largest final squared Mahalanobis error
  std::vector<Eigen::Vector3d> points_world;  ///< [m] optimised points (last solve)
  int rounds = 0;                             ///< [-] solve rounds performed
  int measurements = 0;                       ///< [-] total measurements z_ijk
  int culled_measurements = 0;                ///< [-] measurements dropped as outliers
};

/// Builds all measurements z_ijk (frames in which both endpoints of an edge are observed) and
/// runs up to max_rounds rounds of {linear least squares of J_p + prior; drop measurements whose
/// squared Mahalanobis error exceeds chi2_threshold}. Edges without any measurement are kept
/// (nothing contradicts them). Throws std::invalid_argument on out-of-range indices.
CullingResult CullInconsistentEdges(const CorrelationInput& input,
                                    const std::vector<GraphEdge>& edges,
                                    const CullingOptions& options);

/// Alternative "direct" per-edge test, no point optimisation: rotates each measurement into the
/// world frame (w_k = R_k^T z_ijk, S_k = R_k^T C_ijk R_k), fits the information-weighted mean
/// and tests chi2 = sum (w_k - mean)^T S_k^-1 (w_k - mean) against the chi-square quantile with
/// 3(K-1) degrees of freedom at `probability`. Edges with fewer than 2 measurements are kept.
/// edge_max_chi2 holds the edge's chi2 statistic; points_world is left empty.
CullingResult DirectEdgeTest(const CorrelationInput& input, const std::vector<GraphEdge>& edges,
                             double probability);

/// Quantile of the chi-square distribution with `dof` degrees of freedom at `probability`
/// (Wilson-Hilferty approximation; within 1% of the tables for dof >= 3 and p in [0.9, 0.999]).
double ChiSquareQuantile(int dof, double probability);

}  // namespace dslam
