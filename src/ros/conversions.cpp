#include "dslam/ros/conversions.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <sensor_msgs/image_encodings.h>
#include <opencv2/imgproc.hpp>

#include "dslam/core/depth_conversion.h"
#include "dslam/core/geometry.h"
#include "dslam/tracking/pose_optimizer.h"

namespace dslam {
namespace ros_layer {
namespace enc = sensor_msgs::image_encodings;

std::string NormaliseFrameId(const std::string& frame_id) {
  const size_t first = frame_id.find_first_not_of('/');
  return first == std::string::npos ? std::string() : frame_id.substr(first);
}

namespace {

constexpr bool kHostBigEndian = __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__;

std::string SizeText(uint32_t width, uint32_t height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

/// Copies the pixel rows of `image` into a new continuous Mat of OpenCV `type`, swapping the bytes
/// of multi-byte channels when the message's byte order differs from the host's. Checks size, step
/// and data length first (`what` names the image in the messages).
cv::Mat CopyPixels(const sensor_msgs::Image& image, int type, const std::string& what) {
  if (image.width == 0 || image.height == 0) {
    throw std::invalid_argument(what + " is empty (" + SizeText(image.width, image.height) + ")");
  }
  const size_t pixel_bytes = CV_ELEM_SIZE(type);
  const size_t row_bytes = image.width * pixel_bytes;
  if (image.step < row_bytes) {
    throw std::invalid_argument(what + " step " + std::to_string(image.step) +
                                " is shorter than a row (" + std::to_string(image.width) +
                                " px x " + std::to_string(pixel_bytes) + " bytes of " +
                                image.encoding + ")");
  }
  const size_t needed = static_cast<size_t>(image.step) * image.height;
  if (image.data.size() != needed) {
    throw std::invalid_argument(
        what + (image.data.size() < needed ? " is truncated: " : " is inconsistent: ") +
        std::to_string(image.data.size()) +
        " data bytes, step x height = " + std::to_string(needed));
  }
  cv::Mat out(static_cast<int>(image.height), static_cast<int>(image.width), type);
  for (int r = 0; r < out.rows; ++r) {
    std::memcpy(out.ptr(r), image.data.data() + static_cast<size_t>(r) * image.step, row_bytes);
  }
  const size_t channel_bytes = CV_ELEM_SIZE1(type);
  if (channel_bytes > 1 && (image.is_bigendian != 0) != kHostBigEndian) {
    uint8_t* bytes = out.data;
    const size_t total = out.total() * pixel_bytes;
    for (size_t i = 0; i < total; i += channel_bytes)
      std::reverse(bytes + i, bytes + i + channel_bytes);
  }
  return out;
}

}  // namespace

cv::Mat ColourFromImage(const sensor_msgs::Image& image) {
  const std::string& e = image.encoding;
  const std::string what = "colour image (" + e + ")";
  if (e == enc::BGR8 || e == enc::MONO8) {
    return CopyPixels(image, e == enc::MONO8 ? CV_8UC1 : CV_8UC3, what);
  }
  cv::Mat out;
  if (e == enc::RGB8) {
    cv::cvtColor(CopyPixels(image, CV_8UC3, what), out, cv::COLOR_RGB2BGR);
  } else if (e == enc::RGBA8) {
    cv::cvtColor(CopyPixels(image, CV_8UC4, what), out, cv::COLOR_RGBA2BGR);
  } else if (e == enc::BGRA8) {
    cv::cvtColor(CopyPixels(image, CV_8UC4, what), out, cv::COLOR_BGRA2BGR);
  } else {
    throw std::invalid_argument("colour image encoding '" + e +
                                "' is not supported (accepted: rgb8, bgr8, rgba8, bgra8, mono8; "
                                "subscribe to a debayered topic such as image_color)");
  }
  return out;
}

cv::Mat DepthFromImage(const sensor_msgs::Image& image) {
  const std::string& e = image.encoding;
  const std::string what = "depth image (" + e + ")";
  if (e == enc::TYPE_32FC1) return DepthFromMetres(CopyPixels(image, CV_32FC1, what));
  if (e == enc::TYPE_16UC1 || e == enc::MONO16) {
    return DepthFromMillimetres(CopyPixels(image, CV_16UC1, what));
  }
  throw std::invalid_argument("depth image encoding '" + e +
                              "' is not supported (accepted: 16UC1 or mono16 millimetres, 32FC1 "
                              "metres)");
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

Eigen::Isometry3d MapFromOdom(const Eigen::Isometry3d& T_map_odom_optical,
                              const Eigen::Isometry3d& T_base_camera) {
  // A mount from TF gives T_base_camera * T_base_camera^-1 with round-off.
  if (T_map_odom_optical.matrix() == Eigen::Matrix4d::Identity()) {
    return Eigen::Isometry3d::Identity();
  }
  return OdomFromBase(T_map_odom_optical, T_base_camera);  // the same change of frames
}

Eigen::Matrix<double, 6, 6> OdomCovariance(const Eigen::Matrix<double, 6, 6>& information,
                                           const Eigen::Isometry3d& T_odom_camera,
                                           const Eigen::Isometry3d& T_base_camera,
                                           double unknown_variance) {
  using Matrix6d = Eigen::Matrix<double, 6, 6>;
  if (!InvertibleInformation(information)) return unknown_variance * Matrix6d::Identity();
  // Covariance of [dp; dtheta] of T_odom_camera (left perturbation in the odom optical frame).
  const Matrix6d cov_odom_camera = CovarianceWorldCamera(information, T_odom_camera.inverse());
  // T_odom_base = T_bc T_oc T_cb: dp_ob = R_bc (dp - [R_oc t_cb]x dtheta), dtheta_o = R_bc dtheta.
  const Eigen::Matrix3d R_bc = T_base_camera.rotation();
  const Eigen::Vector3d lever = T_odom_camera.rotation() * T_base_camera.inverse().translation();
  Matrix6d J = Matrix6d::Zero();
  J.block<3, 3>(0, 0) = R_bc;
  J.block<3, 3>(0, 3) = -R_bc * Skew(lever);
  J.block<3, 3>(3, 3) = R_bc;
  return J * cov_odom_camera * J.transpose();
}

}  // namespace ros_layer
}  // namespace dslam
