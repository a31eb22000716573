#pragma once
// Ground truth of the moving objects of a synthetic sequence, as written to objects.txt
// (writer.h): per frame and visible object, the mean of the noise-free 3D points of its mask
// pixels, the velocity of its body and the share of the image it covers, in the world frame of
// groundtruth.txt.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dslam/synth/sequence.h"

namespace dslam {
namespace synth {

/// One moving object seen in one frame.
struct ObjectTruth {
  uint16_t id = 0;           ///< mask id (walkers 1..W, boxes W+1..W+B, sheets after them)
  int pixels = 0;            ///< [px] mask pixels of the object
  double pixel_share = 0.0;  ///< [-] pixels / image pixels
  /// [m] mean of the noise-free 3D points of the object's mask pixels (world frame)
  Eigen::Vector3d centroid_world_m = Eigen::Vector3d::Zero();
  /// [m/s] velocity of the object's body reference point (world frame): walker floor point
  /// (zero while pausing), box centre; zero for sheets (their top edge is fixed)
  Eigen::Vector3d velocity_world_mps = Eigen::Vector3d::Zero();
};

/// [m/s] Velocity (world frame) of the body reference point of the moving object with mask `id`
/// of `scenario` at `t_s` [s] after the start, computed analytically (WalkerVelocityAt,
/// MovingBoxVelocityAt; zero for sheets). Throws std::out_of_range for an id the scenario lacks.
Eigen::Vector3d ObjectVelocityAt(const Scenario& scenario, uint16_t id, double t_s);

/// The objects visible in `frame` (a frame of `sequence`), ids ascending: every id present in
/// frame.mask, its centroid from frame.depth_true_m back-projected by the sequence's camera and
/// moved by frame.T_world_camera, and its velocity at the frame's time index / fps.
std::vector<ObjectTruth> VisibleObjects(const SyntheticSequence& sequence,
                                        const SyntheticFrame& frame);

/// The comment lines (each ending in a newline) that begin objects.txt.
std::string ObjectTruthHeader(const Scenario& scenario);

/// One line of objects.txt without newline: `timestamp id x y z vx vy vz pixel_share` (stamp as
/// FormatStamp, metres and m/s with 6 decimals, share with 6 decimals).
std::string FormatObjectTruth(double stamp_s, const ObjectTruth& object);

}  // namespace synth
}  // namespace dslam
