#pragma once
// Conversions between ROS messages and the core's types: images -> RgbdFrame parts, camera_info
// -> PinholeCamera, poses and covariances -> ROS conventions (REP 103/105).

#include <memory>
#include <string>

#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/core/camera.h"

namespace dslam {
namespace ros_layer {

/// Frame id without leading slashes (TUM bags use "/openni_rgb_optical_frame").
std::string NormaliseFrameId(const std::string& frame_id);

/// rgb8 / bgr8 / mono8 image -> CV_8UC3 BGR or CV_8UC1 grey (a copy).
/// Throws std::invalid_argument naming the encoding otherwise, or the problem of an image whose
/// size or layout CheckImageLayout (dslam/ros/image_layout.h) rejects.
cv::Mat ColourFromImage(const sensor_msgs::Image& image);

/// 16UC1 (millimetres) / 32FC1 (metres) depth -> CV_32FC1 metres, 0 = no measurement (NaN,
/// infinite, zero and negative values become 0). Throws std::invalid_argument otherwise, or as
/// ColourFromImage for a bad size or layout.
cv::Mat DepthFromImage(const sensor_msgs::Image& image);

/// Pinhole camera from K and plumb_bob D (an empty D or all zeros: no distortion).
/// Throws std::invalid_argument on a zero K, a zero size or another distortion model.
std::shared_ptr<const PinholeCamera> CameraFromInfo(const sensor_msgs::CameraInfo& info);

/// Default mount of the camera's optical frame (x right, y down, z forward) on the base frame
/// (REP 103: x forward, y left, z up), at the base origin: T_base_camera maps optical-frame
/// points into the base frame (optical z -> base x, optical x -> base -y, optical y -> base -z).
Eigen::Isometry3d DefaultBaseFromOptical();

/// The base frame's pose in the odom frame for the camera pose T_world_camera, where the odom
/// frame is the base frame at the first frame (world = the first frame's optical frame):
/// T_odom_base = T_base_camera * T_world_camera * T_base_camera^-1.
Eigen::Isometry3d OdomFromBase(const Eigen::Isometry3d& T_world_camera,
                               const Eigen::Isometry3d& T_base_camera);

/// Row-major 6x6 covariance of T_odom_base in ROS order [x y z rx ry rz] (position in the odom
/// frame, rotation about the odom axes) from the pose solver's information (FrameResult::
/// information: [dtheta, dt] of a left perturbation of T_camera_world). Returns `unknown_variance`
/// on the diagonal when the information is not positive definite (first frame, RANSAC pose).
Eigen::Matrix<double, 6, 6> OdomCovariance(const Eigen::Matrix<double, 6, 6>& information,
                                           const Eigen::Isometry3d& T_world_camera,
                                           const Eigen::Isometry3d& T_base_camera,
                                           double unknown_variance = 1e6);

}  // namespace ros_layer
}  // namespace dslam
