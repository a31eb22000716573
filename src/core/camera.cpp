#include "dslam/core/camera.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "dslam/core/image_limits.h"

namespace dslam {

PinholeCamera::PinholeCamera(int width, int height, double fx, double fy, double cx, double cy,
                             const Distortion& distortion)
    : width_(width), height_(height), fx_(fx), fy_(fy), cx_(cx), cy_(cy), distortion_(distortion) {
  CheckImageSize(width, height, "camera");
  if (!(fx > 0.0) || !(fy > 0.0) || !std::isfinite(fx) || !std::isfinite(fy)) {
    throw std::invalid_argument("camera: focal lengths fx, fy must be positive and finite");
  }
  if (!std::isfinite(cx) || !std::isfinite(cy)) {
    throw std::invalid_argument("camera: principal point cx, cy must be finite");
  }
  const Distortion& d = distortion;
  if (!std::isfinite(d.k1) || !std::isfinite(d.k2) || !std::isfinite(d.p1) ||
      !std::isfinite(d.p2) || !std::isfinite(d.k3)) {
    throw std::invalid_argument("camera: distortion coefficients must be finite");
  }
}

Eigen::Vector2d PinholeCamera::Project(const Eigen::Vector3d& p_camera) const {
  return {fx_ * p_camera.x() / p_camera.z() + cx_, fy_ * p_camera.y() / p_camera.z() + cy_};
}

Eigen::Vector3d PinholeCamera::BackProject(const Eigen::Vector2d& uv, double depth_m) const {
  return {(uv.x() - cx_) * depth_m / fx_, (uv.y() - cy_) * depth_m / fy_, depth_m};
}

Eigen::Vector2d PinholeCamera::Distort(const Eigen::Vector2d& uv_ideal) const {
  if (distortion_.IsZero()) return uv_ideal;
  const Distortion& d = distortion_;
  const double x = (uv_ideal.x() - cx_) / fx_;
  const double y = (uv_ideal.y() - cy_) / fy_;
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
  const double xd = x * radial + 2.0 * d.p1 * x * y + d.p2 * (r2 + 2.0 * x * x);
  const double yd = y * radial + d.p1 * (r2 + 2.0 * y * y) + 2.0 * d.p2 * x * y;
  return {fx_ * xd + cx_, fy_ * yd + cy_};
}

Eigen::Vector2d PinholeCamera::Undistort(const Eigen::Vector2d& uv_distorted) const {
  if (distortion_.IsZero()) return uv_distorted;
  // Fixed-point iteration on normalised coordinates: x = (x_d - tangential(x)) / radial(x).
  const Distortion& d = distortion_;
  const double xd = (uv_distorted.x() - cx_) / fx_;
  const double yd = (uv_distorted.y() - cy_) / fy_;
  double x = xd, y = yd;
  for (int i = 0; i < 20; ++i) {
    const double r2 = x * x + y * y;
    const double radial = 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
    const double dx = 2.0 * d.p1 * x * y + d.p2 * (r2 + 2.0 * x * x);
    const double dy = d.p1 * (r2 + 2.0 * y * y) + 2.0 * d.p2 * x * y;
    const double x_next = (xd - dx) / radial, y_next = (yd - dy) / radial;
    // A fixed point: every further iteration would return the same values.
    if (x_next == x && y_next == y) break;
    x = x_next;
    y = y_next;
  }
  return {fx_ * x + cx_, fy_ * y + cy_};
}

bool PinholeCamera::InImage(const Eigen::Vector2d& uv, double border) const {
  return uv.x() >= border && uv.y() >= border && uv.x() <= width_ - 1 - border &&
         uv.y() <= height_ - 1 - border;
}

}  // namespace dslam
