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

/// Colour encodings ColourFromImage() accepts: rgb8, bgr8, rgba8, bgra8 (alpha dropped), mono8.
/// Others (bayer_*, yuv422, 16-bit colour, ...) are rejected: subscribe to a debayered topic
/// (image_proc's image_color / image_rect_color) instead.
/// A colour image -> CV_8UC3 BGR or CV_8UC1 grey (a copy). Throws std::invalid_argument whose
/// text begins "colour image" and names the problem: an unsupported encoding (listing the
/// accepted ones), a zero size, a step shorter than a row or data of another length than
/// step * height (a truncated message is never read out of bounds).
cv::Mat ColourFromImage(const sensor_msgs::Image& image);

/// A depth image -> CV_32FC1 metres, 0 = no measurement. Accepted encodings: 16UC1 and mono16
/// (millimetres, 0 = none) and 32FC1 (metres; NaN, infinite, zero and negative values become 0),
/// either byte order (is_bigendian = 1 is byte-swapped). Throws std::invalid_argument whose text
/// begins "depth image" on another encoding, a zero size or inconsistent step / data size.
cv::Mat DepthFromImage(const sensor_msgs::Image& image);

/// Which intrinsics of a camera_info describe an image (image_pipeline's convention).
enum class ImageGeometry {
  kRaw,        ///< image_raw / image_color: K and the distortion D
  kRectified,  ///< image_rect*: the projection P (fx = P[0], fy = P[5], cx = P[2], cy = P[6]), no D
};

/// Pinhole camera of the colour image `colour` (only its width and height are read) from
/// `info`. kRaw: K with the distortion of `distortion_model` / D; an empty D or one of zeros is
/// no distortion; plumb_bob needs 5 coefficients, rational_polynomial 8 of which k4..k6 must be 0,
/// other models (equidistant, ...) are rejected unless D is all zeros. kRectified: P, D ignored;
/// P[3] (Tx) or P[7] (Ty) non-zero (a right stereo camera) is rejected. Throws
/// std::invalid_argument whose text begins "camera_info" and names the field, e.g.
/// "camera_info K[0] (fx) is NaN", on: a zero size, a size other than the colour image's,
/// binning or a region of interest, a NaN / infinite / non-positive focal length, a NaN /
/// infinite centre or one outside the image, a skew (K[1] or P[1]) other than 0, a NaN /
/// infinite D coefficient, a D length wrong for its model or an unsupported model.
std::shared_ptr<const PinholeCamera> CameraFromInfo(const sensor_msgs::CameraInfo& info,
                                                    const sensor_msgs::Image& colour,
                                                    ImageGeometry geometry);

/// Default mount of the camera's optical frame (x right, y down, z forward) on the base frame
/// (REP 103: x forward, y left, z up), at the base origin: T_base_camera maps optical-frame
/// points into the base frame (optical z -> base x, optical x -> base -y, optical y -> base -z).
Eigen::Isometry3d DefaultBaseFromOptical();

/// The base frame's pose in the odom frame for the camera pose T_world_camera, where the odom
/// frame is the base frame at the first frame (world = the first frame's optical frame):
/// T_odom_base = T_base_camera * T_world_camera * T_base_camera^-1.
Eigen::Isometry3d OdomFromBase(const Eigen::Isometry3d& T_world_camera,
                               const Eigen::Isometry3d& T_base_camera);

/// The map -> odom transform between base frames for OdomIntegrator's T_map_odom (between
/// optical frames: the tracker's world and odom's origin). The map frame is the base frame at the
/// tracker's first frame, odom the base frame where odom started: T_map_odom = T_base_camera *
/// T_map_odom_optical * T_base_camera^-1, exactly the identity when T_map_odom_optical is.
Eigen::Isometry3d MapFromOdom(const Eigen::Isometry3d& T_map_odom_optical,
                              const Eigen::Isometry3d& T_base_camera);

/// Row-major 6x6 covariance of T_odom_base in ROS order [x y z rx ry rz] (position in the odom
/// frame, rotation about the odom axes) from the pose solver's information (FrameResult::
/// information: [dtheta, dt] of a left perturbation of T_camera_world, so of the camera's pose in
/// its own frame) and the camera's pose T_odom_camera in odom (optical frames, OdomIntegrator).
/// Returns `unknown_variance` on the diagonal when the information is not positive definite
/// (first frame, RANSAC pose).
Eigen::Matrix<double, 6, 6> OdomCovariance(const Eigen::Matrix<double, 6, 6>& information,
                                           const Eigen::Isometry3d& T_odom_camera,
                                           const Eigen::Isometry3d& T_base_camera,
                                           double unknown_variance = 1e6);

}  // namespace ros_layer
}  // namespace dslam
