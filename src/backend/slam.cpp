#include "dslam/backend/slam.h"

#include "dslam/backend/window_static_points.h"

namespace dslam {

Slam::Slam(const Config& config) : odometry_(config) {}

FrameResult Slam::ProcessFrame(const RgbdFrame& frame) {
  // Front end (Sec. V-A, V-B): features, local-map matching, pose from static points, front-end
  // static point determination, map management and keyframes.
  FrameResult result = odometry_.ProcessFrame(frame);
  if (result.has_pose) refined_.AddFrame(result.stamp_s, result.T_world_camera, map());
  // Back end (Sec. V): local mapping on the window the new keyframe completes.
  if (result.keyframe && config().backend.enabled) result.backend = RunLocalMapping();
  return result;
}

BackEndStatus Slam::RunLocalMapping() {
  BackEndStatus status;
  // Algorithm 1 over the window first: local BA then uses only the points that stayed marked.
  if (config().backend.spd_enabled && config().static_points.enabled) {
    const WindowStaticPointsStats spd =
        DetermineStaticPointsInWindow(config(), odometry_.mutable_map());
    status.spd_ran = spd.ran;
    status.spd_keyframes = spd.keyframes;
    status.spd_points = spd.points;
    status.spd_edges = spd.edges;
    status.spd_culled_edges = spd.culled_edges;
    status.spd_unmarked = spd.unmarked;
    status.spd_graph_ms = spd.graph_ms;
    status.spd_culling_ms = spd.culling_ms;
    status.spd_components_ms = spd.components_ms;
    status.spd_ms = spd.total_ms;
  }
  const LocalBaStats ba = LocalBundleAdjustment(config().backend, odometry_.mutable_map());
  // Tracking goes on from the refined pose of the keyframe just made (this frame).
  if (ba.ran && !ba.rejected) {
    odometry_.AdoptNewestKeyFramePose();
    refined_.UpdateKeyFrames(map());
  }
  status.ran = ba.ran;
  status.window_keyframes = static_cast<int>(map().keyframes().size());
  status.ba_keyframes = ba.keyframes;
  status.ba_points = ba.points;
  status.ba_measurements = ba.measurements;
  status.ba_outliers = ba.outliers;
  status.ba_iterations = ba.iterations;
  status.ba_rejected = ba.rejected;
  status.ba_ms = ba.time_ms;
  return status;
}

}  // namespace dslam
