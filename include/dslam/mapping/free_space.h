#pragma once
// The free-space (visibility) check of the static map: a keyframe's depth image, reduced to
// blocks, votes on a world point. When the depth it measured along the point's ray lies clearly
// beyond the point, the keyframe saw through it: the point was not there at that keyframe's time
// (transient: a person who walked on) or never was (a depth artefact). When it measured the
// point's depth, it saw a surface there (support). Nearer depth (an occluder) and no depth give
// no vote.

#include <memory>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/core/camera.h"
#include "dslam/core/map_config.h"
#include "dslam/core/rgbd_frame.h"

namespace dslam {

/// What one keyframe's depth says about a point.
enum class Visibility {
  kNoVote,      ///< outside the image or the depth range, no depth nearby, or occluded
  kSupport,     ///< a surface measured at the point's depth (within the margin)
  kSeeThrough,  ///< every depth measured around its pixel lies beyond it by more than the margin
};

/// Tolerances of the vote (MapConfig's free_space_* fields).
struct FreeSpaceTolerance {
  double margin_m = 0.1;      ///< [m] constant part of the margin
  double margin_ratio = 0.0;  ///< [-] part of the margin proportional to the point's depth
  double min_depth_m = 0.0;   ///< [m] points nearer to the camera get no vote
  double max_depth_m = 1e9;   ///< [m] points farther from the camera get no vote
  int min_misses = 1;         ///< [-] see-throughs needed to call a point transient (map: 1)

  /// The tolerances of `config`, with the depth range [min_depth_m, max_depth_m] [m] (the depth
  /// model's, depth_noise) and min_misses 1.
  static FreeSpaceTolerance From(const MapConfig& config, double min_depth_m, double max_depth_m);
  /// Whether a point with `misses` see-throughs and `hits` supports (its own keyframes
  /// included) is transient: misses >= min_misses and misses >= hits.
  bool Transient(int misses, int hits) const { return misses >= min_misses && misses >= hits; }
  /// Whether a point at `depth_m` [m] from the camera gets a vote: within [min_depth_m,
  /// max_depth_m] (NaN: no).
  bool InRange(double depth_m) const { return depth_m >= min_depth_m && depth_m <= max_depth_m; }
  /// [m] the margin at `depth_m` [m]: margin_m + margin_ratio depth_m.
  double Margin(double depth_m) const { return margin_m + margin_ratio * depth_m; }
};

/// A keyframe's depth image reduced to blocks of block_px x block_px pixels, each the nearest
/// valid depth within its 3x3 neighbourhood of blocks (so a vote holds across a block and its
/// neighbours: depth edges give occlusion, not see-through), with the keyframe's pose.
class DepthView {
 public:
  /// `frame.depth_m` in metres (0, NaN: none), `block_px` >= 1. Depths below `min_depth_m` count
  /// as none; far depths are kept (a far measurement still shows the free space before it; the
  /// tolerance's max_depth_m limits the points voted on).
  DepthView(const RgbdFrame& frame, const Eigen::Isometry3d& T_world_camera, int block_px,
            double min_depth_m);

  /// A view of `camera` from depths already reduced to blocks: `block_depth_m` (CV_32FC1,
  /// ceil(height / block_px) x ceil(width / block_px)) holds one depth [m] per block (infinity:
  /// none, never NaN), e.g. one sampled pixel per block; each block's nearest depth of its 3x3
  /// neighbourhood is taken as above.
  DepthView(std::shared_ptr<const PinholeCamera> camera, const Eigen::Isometry3d& T_world_camera,
            int block_px, const cv::Mat& block_depth_m);

  /// The vote of this view on `p_world` [m, world frame].
  Visibility Vote(const Eigen::Vector3f& p_world, const FreeSpaceTolerance& tolerance) const;

  /// The vote of this view on `p_camera` [m], a point already in this view's optical frame
  /// (Vote() of T_camera_world() * p_world).
  Visibility VoteInView(const Eigen::Vector3f& p_camera, const FreeSpaceTolerance& tolerance) const;

  /// Sets the keyframe's pose (optical frame -> world) [m].
  void set_pose(const Eigen::Isometry3d& T_world_camera);
  /// The keyframe's pose inverted (world -> optical frame) [m].
  const Eigen::Isometry3f& T_camera_world() const { return T_camera_world_; }

 private:
  std::shared_ptr<const PinholeCamera> camera_;
  bool distorted_;  ///< whether camera_ has a distortion model (not all zero)
  Eigen::Isometry3f T_camera_world_;
  int block_px_;
  int block_shift_ = -1;  ///< log2(block_px_) when block_px_ is a power of two, else -1
  cv::Mat near_m_;  ///< CV_32FC1 per block: nearest valid depth of the 3x3 blocks [m]; inf: none
};

}  // namespace dslam
