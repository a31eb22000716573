#pragma once
// Motion-only bundle adjustment: the camera pose from map points and their measurements in the
// current frame, with the paper's RGB-D measurement model (Eq. rgbd_yik: y_ik = s(T_k p_i) + n,
// n ~ N(0, C_ik)) and a 2D reprojection residual for features without depth.
//
// Rounds (after ORB-SLAM2's PoseOptimization): optimise the current inliers (all in round 1) with a
// Huber loss, then re-classify EVERY observation by its squared Mahalanobis error at the new pose
// (chi2_depth for 3 dof, chi2_pixel for 2 dof); the last classification is returned.

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/core/camera.h"
#include "dslam/core/depth_uncertainty.h"
#include "dslam/core/features_config.h"

namespace dslam {

/// One map point observed in the current frame.
struct PoseObservation {
  Eigen::Vector3d p_world = Eigen::Vector3d::Zero();  ///< [m] map point, world frame
  bool has_depth = false;  ///< true: 3D residual on y_camera; false: 2D residual on uv_ideal
  Eigen::Vector3d y_camera = Eigen::Vector3d::Zero();        ///< [m] measured point, optical frame
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  ///< [m^2] C of the 3D residual
  Eigen::Vector2d uv_ideal = Eigen::Vector2d::Zero();        ///< [px] undistorted keypoint
  double pixel_sigma_px = 1.0;  ///< [px] sigma of the 2D residual (e.g. 1 px x octave scale)

  /// RGB-D observation from MeasurePoint(); pass C_ik, or C_ik plus the map point's covariance
  /// rotated into the camera frame when it is known.
  static PoseObservation WithDepth(const Eigen::Vector3d& p_world, const PointMeasurement& m);
  /// Pixel-only observation (no depth).
  static PoseObservation PixelOnly(const Eigen::Vector3d& p_world, const Eigen::Vector2d& uv_ideal,
                                   double pixel_sigma_px);
};

/// Result of EstimatePose().
struct PoseResult {
  bool success = false;  ///< false: fewer than 3 usable observations or solver failure
  Eigen::Isometry3d T_camera_world = Eigen::Isometry3d::Identity();  ///< world -> optical frame
  std::vector<bool> inliers;  ///< per observation, chi-square classification at the final pose
  int num_inliers = 0;
  int num_observations = 0;  ///< observations the rounds classified (inliers and gated out)
  /// [-] mean whitened squared error per degree of freedom (3 with depth, 2 without) over the
  /// inliers at the final pose: about 0.88 (3 dof) or 0.84 (2 dof) when the errors fit their
  /// model, truncated at the 95 % bounds.
  double inlier_chi2_per_dof = 0.0;
  double final_cost = 0.0;  ///< [-] 1/2 sum of robustified squared whitened residuals (inliers)
  int iterations = 0;       ///< solver iterations summed over rounds
  /// [-] 6x6 information J^T J of the inlier residuals (whitened, without the Huber weights) at
  /// the solution, parameter order [dtheta (3, rad), dt (3, m)] for the perturbation
  /// T_camera_world <- (Exp(dtheta) R_camera_world, t_camera_world + dt) (rotation perturbed on
  /// the left, i.e. about the camera axes). See CovarianceWorldCamera() for ROS.
  Eigen::Matrix<double, 6, 6> information = Eigen::Matrix<double, 6, 6>::Zero();
};

/// How EstimatePose solves each round. dslam runs kLevenbergMarquardt (pose_solver_lm.cpp);
/// kCeres solves the same cost with Ceres: the reference the tests and dslam_features_bench check
/// the hand-written solver against (docs/benchmarks/tracking.md, "Motion-only BA solver": the same
/// trajectories, slower).
enum class PoseSolver { kLevenbergMarquardt, kCeres };

/// Motion-only BA from `T_camera_world_guess`; see the top of this file. `camera` supplies the
/// intrinsics of the pixel residuals. Huber widths apply to the whitened residual norm. The first
/// round uses the observations flagged in `initial_inliers` (all when null or empty).
PoseResult EstimatePose(const std::vector<PoseObservation>& observations,
                        const Eigen::Isometry3d& T_camera_world_guess, const PinholeCamera& camera,
                        const PoseConfig& config,
                        const std::vector<bool>* initial_inliers = nullptr,
                        PoseSolver solver = PoseSolver::kLevenbergMarquardt);

/// Squared Mahalanobis error of one observation at a pose (3 dof with depth, 2 dof without).
double SquaredError(const PoseObservation& observation, const Eigen::Isometry3d& T_camera_world,
                    const PinholeCamera& camera);

/// Jacobian of Eigen's rotation q * p = p + 2w (u x p) + 2u x (u x p), u = (q.x, q.y, q.z), with
/// respect to the coefficients (q.x, q.y, q.z, q.w) [m per unit coefficient]; exact for any q, unit
/// or not (the motion-only BA's analytic residual Jacobians, before the quaternion manifold).
Eigen::Matrix<double, 3, 4> RotatedPointByQuaternion(const Eigen::Quaterniond& q,
                                                     const Eigen::Vector3d& p);

/// Jacobian [6x6] mapping the solver perturbation [dtheta_c, dt_c] of T_camera_world to the ROS
/// pose perturbation [dp_w (3, m), dtheta_w (3, rad)] of T_world_camera (position in the world
/// frame, rotation about the fixed world axes, nav_msgs/Odometry covariance order).
Eigen::Matrix<double, 6, 6> PerturbationToWorldCamera(const Eigen::Isometry3d& T_camera_world);

/// Whether a 6x6 pose information (PoseResult::information) can be inverted into a covariance:
/// nonzero and positive definite, its smallest LDLT pivot above 1e-12 of the largest (at least
/// 1e-12). Zero for the first frame and a failed solve.
bool InvertibleInformation(const Eigen::Matrix<double, 6, 6>& information);

/// Covariance [m^2, rad^2] of T_world_camera in ROS order [x y z rx ry rz] from the information
/// of T_camera_world (PoseResult::information): A info^-1 A^T with A =
/// PerturbationToWorldCamera(). The information must be positive definite.
Eigen::Matrix<double, 6, 6> CovarianceWorldCamera(const Eigen::Matrix<double, 6, 6>& information,
                                                  const Eigen::Isometry3d& T_camera_world);

/// CovarianceWorldCamera() of a successful result.
inline Eigen::Matrix<double, 6, 6> CovarianceWorldCamera(const PoseResult& result) {
  return CovarianceWorldCamera(result.information, result.T_camera_world);
}

}  // namespace dslam
