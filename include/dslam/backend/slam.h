#pragma once
// The whole pipeline of the paper, synchronous: the front end (Odometry: ORB tracking against the
// local map with front-end static point determination) on every frame and, after each new
// keyframe, the back end (local bundle adjustment over the keyframe window) on the same map
// before the next frame is read. Deterministic: the reference for offline runs.

#include "dslam/backend/local_bundle_adjustment.h"
#include "dslam/backend/refined_trajectory.h"
#include "dslam/core/config.h"
#include "dslam/core/rgbd_frame.h"
#include "dslam/tracking/frame_result.h"
#include "dslam/tracking/odometry.h"

namespace dslam {

/// Front end and back end over one map. Not thread-safe: call from one thread.
class Slam {
 public:
  /// Throws ConfigError when `config` is invalid.
  explicit Slam(const Config& config);

  /// Tracks one frame (Odometry::ProcessFrame) and, when it became a keyframe and
  /// backend.enabled, runs local mapping; FrameResult::backend reports what it did. The pose in
  /// the result is the one estimated at this frame (causal), before the back end refines the map.
  /// Throws std::invalid_argument when frame.Check() fails.
  FrameResult ProcessFrame(const RgbdFrame& frame);

  /// Forgets the map and the motion model; the next frame initialises at the world origin.
  void Reset() { odometry_.Reset(); }

  const Map& map() const { return odometry_.map(); }  ///< the shared map (for visualisation)

  /// Every tracked frame re-expressed on its reference keyframe as refined by the back end so
  /// far (RefinedTrajectory); the same poses as the causal ones with the back end off.
  Trajectory RefinedPoses() const { return refined_.Poses(); }
  const Config& config() const { return odometry_.config(); }

 private:
  BackEndStatus RunLocalMapping();

  Odometry odometry_;
  RefinedTrajectory refined_;
};

}  // namespace dslam
