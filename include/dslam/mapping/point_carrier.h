#pragma once
// Keeps the points of moving things measured from frame to frame when the front end's matching
// loses them. A walker at 1-2 m moving at 1-1.5 m/s shifts 10-20 px per frame, beyond the local
// map search radius, so most of its points are new in each frame and have no earlier position:
// no point velocity, and a region without velocities neither confirms a track as moving nor
// splits from another thing (object_tracker.h, region_split.h).
//
// The points of the previous frame's regions that this frame's matching did not find are tracked
// into this frame by pyramidal Lucas-Kanade optical flow on the grey images at half resolution
// (an 11 px window at that resolution, 3 levels; forward, then backward to the previous image:
// the round trip must come back within 0.5 full-resolution pixels), at most 500 per frame (evenly
// spread over the lost points: bounds the time per frame). A tracked point joins the region whose
// mask cell it lands in, measured again from this frame's depth, under its own id, so its velocity
// and its position history continue. It is dropped when it lands outside the mask (on the
// background: the flow slid off the moving thing's silhouette), on a cell without valid depth, on a
// cell that already holds a point (at most one point per cell: the points cannot pile up), or
// farther from its previous position than ObjectsConfig::max_point_speed_mps allows in the time
// between the frames (its depth now measured on another surface: at an occlusion border the flow
// follows the image, not the thing). The front end's pose and map never see these points.
//
// The work comes in two halves so that the flow, which needs no mask, can run beside the
// dynamic mask's computation: Track (pyramid and flow) and Attach (the mask's regions).

#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/core/objects_config.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/mapping/dynamic_mask.h"
#include "dslam/tracking/frame_result.h"

namespace dslam {

/// The previous frame's region points tracked into one frame (PointCarrier::Track).
struct CarriedFlow {
  std::vector<cv::Mat> pyramid;             ///< the frame's flow pyramid (empty: not built)
  std::vector<PointId> ids;                 ///< the points that the flow followed both ways
  std::vector<cv::Point2f> uv_raw;          ///< [px] where each landed, full-resolution raw image
  std::vector<Eigen::Vector3d> from_world;  ///< [m] its previous position, world frame
};

/// Optical-flow carrying of the dynamic regions' points between consecutive frames (one thread
/// at a time; Track may run beside the dynamic mask's computation).
class PointCarrier {
 public:
  static constexpr int kWindowPx = 11;        ///< [px] optical flow window side (half resolution)
  static constexpr int kLevels = 3;           ///< optical flow pyramid levels
  static constexpr double kMaxErrorPx = 0.5;  ///< [px] largest forward-backward error (full res.)
  static constexpr int kMaxPoints = 500;      ///< most points carried per frame

  /// Uses config.max_point_speed_mps, and max_depth_m of `mask_config` for the depth of a carried
  /// point.
  PointCarrier(const ObjectsConfig& config, const DynamicMaskConfig& mask_config);

  /// First half: builds the pyramid of `frame` and tracks the previous frame's region points
  /// that `points` (the frame's matched points) lacks, at most kMaxPoints of them (evenly
  /// spread), keeping those whose backward flow returns within kMaxErrorPx. Reads the
  /// previous frame only; nothing when there is none or its image size differs.
  CarriedFlow Track(const RgbdFrame& frame, const std::vector<ObservedPoint>& points);

  /// Second half: adds the points of `flow` (from Track of the same frame) to the regions of
  /// `mask` (see above; positions in the world frame of `T_world_camera`, optical frame ->
  /// world), then remembers this frame's region points (`points`' keypoints and the carried
  /// points' pixels) and pyramid for the next frame. Returns the number of points added.
  int Attach(CarriedFlow flow, const RgbdFrame& frame, const Eigen::Isometry3d& T_world_camera,
             const std::vector<ObservedPoint>& points, DynamicMask* mask);

  /// Track and Attach one after the other. Call with consecutive frames; Reset() after a gap.
  int Carry(const RgbdFrame& frame, const Eigen::Isometry3d& T_world_camera,
            const std::vector<ObservedPoint>& points, DynamicMask* mask) {
    return Attach(Track(frame, points), frame, T_world_camera, points, mask);
  }

  /// Forgets the previous frame (its points are not carried into the next one).
  void Reset();

 private:
  /// The half-resolution grey pyramid of `frame`, built into the images of spare_pyramid_.
  std::vector<cv::Mat> Pyramid(const RgbdFrame& frame);
  /// Remembers the region points of `mask` at their pixels (`points`' keypoints, or `carried`'s
  /// pixels for the points it added) with `pyramid` and the frame's stamp.
  void Remember(const DynamicMask& mask, const std::vector<ObservedPoint>& points,
                const std::vector<std::pair<PointId, cv::Point2f>>& carried,
                std::vector<cv::Mat> pyramid, double stamp_s);

  cv::Size window_;
  int levels_;
  double max_error_px_;
  double max_speed_mps_;
  int max_points_;
  double max_depth_m_;
  double previous_stamp_s_ = 0.0;                ///< [s]
  std::vector<cv::Mat> previous_pyramid_;        ///< empty: nothing to carry from
  std::vector<cv::Mat> spare_pyramid_;           ///< the one before: its images are reused
  std::vector<PointId> previous_ids_;            ///< previous frame's region points
  std::vector<cv::Point2f> previous_uv_raw_;     ///< [px] their pixels, raw image, same order
  std::vector<Eigen::Vector3d> previous_world_;  ///< [m] their positions, world frame
};

}  // namespace dslam
