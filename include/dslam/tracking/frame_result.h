#pragma once
// What the odometry reports for each frame: state, pose, per-point labels, graph edges, counts
// and per-stage times. Consumed by the offline runner (status CSV, segmentation score) and by
// the ROS layer (odometry, clouds, markers, status message).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dslam/tracking/backend_status.h"
#include "dslam/tracking/map.h"

namespace dslam {

/// Tracking state of one frame.
enum class TrackingState {
  kInitialised,  ///< first frame (or first after a reset): map created, pose = last known pose
  kTracking,     ///< pose from static points of the local map
  kRecovered,    ///< pose from a RANSAC (static points too few) or relocalised by descriptors
  kLost,         ///< no trustworthy pose: none is reported
  /// started in a loaded keyframe map (Odometry::StartInMap) and not yet relocalised in it: no
  /// pose is reported
  kLocalising,
};

/// Lower-case name of a state ("tracking", ...), as written to the status CSV.
const char* ToString(TrackingState state);

/// A map point matched in the frame, with its label at the end of the frame.
struct ObservedPoint {
  PointId id = -1;
  Eigen::Vector2d uv_raw = Eigen::Vector2d::Zero();   ///< [px] keypoint in the raw colour image
  Eigen::Vector3d p_world = Eigen::Vector3d::Zero();  ///< [m] map point position, world frame
  bool is_static = true;      ///< marked (not known to move) at the end of the frame
  bool is_candidate = false;  ///< marked but not yet verified: not used for the pose
};

/// An edge of the front-end Delaunay graph, for visualisation.
struct GraphEdgeView {
  Eigen::Vector3d a_world, b_world;  ///< [m] endpoints, world frame
  bool kept = true;                  ///< false: culled as inconsistent
};

/// Counts of one frame.
struct FrameCounts {
  int features = 0;             ///< ORB keypoints extracted
  int features_with_depth = 0;  ///< of which with a valid depth measurement
  int tracked = 0;              ///< map points matched in the frame
  int static_points = 0;        ///< matched and marked at the end of the frame
  int dynamic_points = 0;       ///< matched and unmarked at the end of the frame
  int candidate_points = 0;     ///< of the static points: candidates not yet verified
  int pose_inliers = 0;         ///< inliers of the final pose estimate
  int pose_observations = 0;    ///< observations of the final pose estimate (inliers and gated out)
  /// [-] the final pose's mean whitened squared error per degree of freedom over its inliers
  /// (PoseResult::inlier_chi2_per_dof)
  double pose_chi2_per_dof = 0.0;
  int graph_points = 0;         ///< points in the front-end graph
  int graph_edges = 0;          ///< edges in the front-end graph
  int culled_edges = 0;         ///< inconsistent edges removed
  int map_points = 0;           ///< map size after the frame
  int new_points = 0;           ///< map points created (keyframes only)
};

/// How FrameResult::backend relates to the frame when Slam runs the back end on its own thread
/// (see dslam/backend/slam.h); all false / zero in synchronous mode, where `backend` is the run
/// after this frame's own keyframe.
struct BackEndThreadStatus {
  bool threaded = false;  ///< the back end runs on its own thread (BackEndMode::kThreaded)
  /// `backend` is a run that completed before this frame and no earlier FrameResult reported.
  bool delivered = false;
  int backlog = 0;  ///< [keyframes] queued for the back end and not yet started, after this frame
};

/// Wall-clock time of each stage [ms].
struct StageTimes {
  double features_ms = 0.0;  ///< ORB extraction and depth measurements
  double matching_ms = 0.0;  ///< local-map projection and search
  /// motion-only BA with marked points (and RANSAC fallback), with the static points' Delaunay
  /// graph built beside it
  double initial_pose_ms = 0.0;
  /// front-end static point determination after the graph, with more matches searched beside it
  double static_points_ms = 0.0;
  double refine_ms = 0.0;   ///< pose refinement with static points
  double mapping_ms = 0.0;  ///< keyframe, new points, culling
  double total_ms = 0.0;    ///< the whole ProcessFrame call
  /// The calling (tracking) thread's time in Slam::ProcessFrame: waiting for the map lock, the
  /// front end and its bookkeeping, never the back end's local mapping (0 from Odometry alone).
  double tracking_ms = 0.0;
};

/// Everything the odometry reports about one frame.
struct FrameResult {
  int frame_index = 0;   ///< 0-based count of frames since the last reset
  double stamp_s = 0.0;  ///< [s] stamp of the frame
  TrackingState state = TrackingState::kLost;
  bool has_pose = false;  ///< false when lost: T_world_camera is then meaningless
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();  ///< optical frame -> world
  /// This frame's pose was tracked from the previous frame's: the previous frame of this world
  /// ended with a pose tracking went on from (tracked, recovered or (re-)initialised) and this
  /// frame has a pose not found by relocalisation. False on the first frame, after a lost frame
  /// or a reset (Odometry::Reset, time going backwards) and on a relocalised frame: the motion
  /// from the previous pose is then a jump, not measured odometry.
  bool has_previous_pose = false;
  /// [optical frame -> world] With has_previous_pose: the previous frame's pose as tracking went
  /// on from it to this frame (Odometry::T_world_last_camera() when this frame began, so after
  /// the back end's corrections between the two frames): the tracked motion between the frames is
  /// T_world_previous_camera^-1 * T_world_camera, whether or not a correction came between.
  Eigen::Isometry3d T_world_previous_camera = Eigen::Isometry3d::Identity();
  /// Information matrix of the pose (6x6, tangent order [rotation; translation] of a
  /// perturbation applied on the left of T_camera_world; from the final pose solve).
  Eigen::Matrix<double, 6, 6> information = Eigen::Matrix<double, 6, 6>::Zero();
  bool keyframe = false;  ///< a keyframe was made from this frame
  bool reset = false;     ///< the odometry reset before this frame (e.g. time went backwards)
  /// This frame re-anchored the map made since a weak episode onto the older map
  /// (reanchoring.h): the correction applied; std::nullopt otherwise. T_world_camera and
  /// T_world_previous_camera are already in the corrected world.
  std::optional<MapCorrection> reanchored;
  std::string message;    ///< why the frame was lost / reset, empty otherwise
  FrameCounts counts;
  StageTimes times;
  BackEndStatus backend;              ///< filled by Slam after keyframes (backend_status.h)
  std::vector<ObservedPoint> points;  ///< matched map points with their labels
  std::vector<GraphEdgeView> edges;   ///< front-end graph (kept and culled edges)
  /// Threaded mode: which back-end run `backend` is, and the back end's backlog.
  BackEndThreadStatus backend_thread;
};

}  // namespace dslam
