#include "dslam/ros/conversions.h"

#include <stdexcept>

#include <cv_bridge/cv_bridge.h>
#include <sensor_msgs/image_encodings.h>
#include <opencv2/imgproc.hpp>

#include "dslam/core/depth_conversion.h"
#include "dslam/core/geometry.h"
#include "dslam/ros/image_layout.h"
#include "dslam/tracking/pose_optimizer.h"

namespace dslam {
namespace ros_layer {
namespace enc = sensor_msgs::image_encodings;

std::string NormaliseFrameId(const std::string& frame_id) {
  const size_t first = frame_id.find_first_not_of('/');
  return first == std::string::npos ? std::string() : frame_id.substr(first);
}

cv::Mat ColourFromImage(const sensor_msgs::Image& image) {
  const std::string& e = image.encoding;
  if (e != enc::RGB8 && e != enc::BGR8 && e != enc::MONO8) {
    throw std::invalid_argument("colour encoding '" + e + "' is not rgb8, bgr8 or mono8");
  }
  CheckImageLayout(image);
  const cv_bridge::CvImageConstPtr cv = cv_bridge::toCvShare(image, nullptr);
  cv::Mat out;
  if (e == enc::RGB8)
    cv::cvtColor(cv->image, out, cv::COLOR_RGB2BGR);
  else
    out = cv->image.clone();
  return out;
}

cv::Mat DepthFromImage(const sensor_msgs::Image& image) {
  const std::string& e = image.encoding;
  if (e != enc::TYPE_16UC1 && e != enc::TYPE_32FC1 && e != enc::MONO16) {
    throw std::invalid_argument("depth encoding '" + e +
                                "' is not 16UC1 (millimetres) or 32FC1 (metres)");
  }
  CheckImageLayout(image);
  const cv_bridge::CvImageConstPtr cv = cv_bridge::toCvShare(image, nullptr);
  if (e == enc::TYPE_32FC1) return DepthFromMetres(cv->image);
  return DepthFromMillimetres(cv->image);
}

std::shared_ptr<const PinholeCamera> CameraFromInfo(const sensor_msgs::CameraInfo& info) {
  if (info.width == 0 || info.height == 0 || info.K[0] <= 0.0 || info.K[4] <= 0.0) {
    throw std::invalid_argument("camera_info has no size or no intrinsics (K)");
  }
  Distortion d;
  bool any = false;
  for (double c : info.D) any = any || c != 0.0;
  if (any) {
    if (info.distortion_model != "plumb_bob" && info.distortion_model != "rational_polynomial") {
      throw std::invalid_argument("camera_info distortion model '" + info.distortion_model +
                                  "' is not plumb_bob");
    }
    const auto at = [&](size_t i) { return i < info.D.size() ? info.D[i] : 0.0; };
    for (size_t i = 5; i < info.D.size(); ++i) {
      if (info.D[i] != 0.0) throw std::invalid_argument("rational_polynomial k4..k6 unsupported");
    }
    d.k1 = at(0), d.k2 = at(1), d.p1 = at(2), d.p2 = at(3), d.k3 = at(4);
  }
  return std::make_shared<const PinholeCamera>(info.width, info.height, info.K[0], info.K[4],
                                               info.K[2], info.K[5], d);
}

Eigen::Isometry3d DefaultBaseFromOptical() {
  Eigen::Matrix3d R_base_optical;
  // Columns: optical x, y, z axes expressed in the base frame.
  R_base_optical << 0, 0, 1,  //
      -1, 0, 0,               //
      0, -1, 0;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R_base_optical;
  return T;
}

Eigen::Isometry3d OdomFromBase(const Eigen::Isometry3d& T_world_camera,
                               const Eigen::Isometry3d& T_base_camera) {
  return T_base_camera * T_world_camera * T_base_camera.inverse();
}

Eigen::Matrix<double, 6, 6> OdomCovariance(const Eigen::Matrix<double, 6, 6>& information,
                                           const Eigen::Isometry3d& T_world_camera,
                                           const Eigen::Isometry3d& T_base_camera,
                                           double unknown_variance) {
  using Matrix6d = Eigen::Matrix<double, 6, 6>;
  const Eigen::LDLT<Matrix6d> ldlt(information);
  if (information.isZero() || ldlt.info() != Eigen::Success || !ldlt.isPositive() ||
      ldlt.vectorD().minCoeff() <= 1e-12 * std::max(1.0, ldlt.vectorD().maxCoeff())) {
    return unknown_variance * Matrix6d::Identity();
  }
  // Covariance of [dp; dtheta] of T_world_camera (left perturbation in the world frame).
  const Matrix6d cov_world_camera = CovarianceWorldCamera(information, T_world_camera.inverse());
  // T_odom_base = T_bc T_wc T_cb: dp_ob = R_bc (dp - [R_wc t_cb]x dtheta), dtheta_o = R_bc dtheta.
  const Eigen::Matrix3d R_bc = T_base_camera.rotation();
  const Eigen::Vector3d lever = T_world_camera.rotation() * T_base_camera.inverse().translation();
  Matrix6d J = Matrix6d::Zero();
  J.block<3, 3>(0, 0) = R_bc;
  J.block<3, 3>(0, 3) = -R_bc * Skew(lever);
  J.block<3, 3>(3, 3) = R_bc;
  return J * cov_world_camera * J.transpose();
}

}  // namespace ros_layer
}  // namespace dslam
