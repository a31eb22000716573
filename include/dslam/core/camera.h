#pragma once
// Pinhole camera with optional radial-tangential (plumb-bob) distortion. Pixel coordinates are
// (u right, v down) in pixels; 3D points are in the camera's optical frame (x right, y down,
// z forward), metres.

#include <Eigen/Core>

namespace dslam {

/// Radial-tangential distortion coefficients (OpenCV / ROS plumb_bob order k1 k2 p1 p2 k3).
struct Distortion {
  double k1 = 0.0, k2 = 0.0, p1 = 0.0, p2 = 0.0, k3 = 0.0;

  /// True when every coefficient is zero (undistortion is then the identity).
  bool IsZero() const { return k1 == 0.0 && k2 == 0.0 && p1 == 0.0 && p2 == 0.0 && k3 == 0.0; }
};

/// Intrinsics of a pinhole camera plus distortion. Immutable after construction.
class PinholeCamera {
 public:
  /// Throws std::invalid_argument for a size outside dslam/core/image_limits.h (CheckImageSize),
  /// a focal length that is not positive and finite, or a non-finite principal point or
  /// distortion coefficient.
  PinholeCamera(int width, int height, double fx, double fy, double cx, double cy,
                const Distortion& distortion = Distortion());

  int width() const { return width_; }    ///< [px]
  int height() const { return height_; }  ///< [px]
  double fx() const { return fx_; }       ///< [px]
  double fy() const { return fy_; }       ///< [px]
  double cx() const { return cx_; }       ///< [px]
  double cy() const { return cy_; }       ///< [px]
  const Distortion& distortion() const { return distortion_; }

  /// Projects a point in the optical frame [m] to ideal (undistorted) pixel coordinates [px].
  /// The point must have z > 0.
  Eigen::Vector2d Project(const Eigen::Vector3d& p_camera) const;

  /// Back-projects ideal pixel coordinates [px] with depth z [m] to the optical frame [m]
  /// (the paper's y_ik = [(u-c_u) d/f_u, (v-c_v) d/f_v, d], Eq. for RGB-D map-point measurement).
  Eigen::Vector3d BackProject(const Eigen::Vector2d& uv, double depth_m) const;

  /// Applies the distortion model to ideal pixel coordinates [px].
  Eigen::Vector2d Distort(const Eigen::Vector2d& uv_ideal) const;

  /// Inverts Distort() by fixed-point iteration [px]; the identity without distortion.
  Eigen::Vector2d Undistort(const Eigen::Vector2d& uv_distorted) const;

  /// True when (u, v) lies inside the image with at least `border` pixels to spare.
  bool InImage(const Eigen::Vector2d& uv, double border = 0.0) const;

 private:
  int width_, height_;
  double fx_, fy_, cx_, cy_;
  Distortion distortion_;
};

}  // namespace dslam
