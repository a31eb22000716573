#include "dslam/mapping/static_mapper.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

#include "dslam/core/keyframe_motion.h"
#include "dslam/mapping/coloured_cloud.h"
#include "dslam/mapping/view_votes.h"

namespace dslam {
namespace {

const Config& Validated(const Config& config) {
  config.Validate();
  return config;
}

ColouredPoint Transformed(const Eigen::Isometry3f& T, const ColouredPoint& point) {
  ColouredPoint out = point;
  out.p = T * point.p;
  return out;
}

}  // namespace

StaticMapper::StaticMapper(const Config& config)
    : config_(Validated(config).map),
      mask_config_(config.dynamic_mask),
      tolerance_(FreeSpaceTolerance::From(config.map, config.depth_noise.min_depth_m,
                                          config.depth_noise.max_depth_m)),
      min_depth_m_(config.depth_noise.min_depth_m),
      back_projection_(BackProjection::Of(config.map, config.depth_noise)),
      voxels_(config.map.voxel_size_m),
      max_fused_kept_(static_cast<size_t>(config.tracking.max_keyframes)) {}

StaticMapper::WindowKeyFrame StaticMapper::Prepare(const KeyFrameRecord& keyframe) const {
  const cv::Mat mask = config_.dynamic_masks ? DynamicPixelMask(keyframe, mask_config_) : cv::Mat();
  return WindowKeyFrame{
      keyframe.id, keyframe.T_world_camera,
      BackProjectKeyFrame(keyframe.frame, mask, back_projection_),
      DepthView(keyframe.frame, keyframe.T_world_camera, config_.pixel_step, min_depth_m_)};
}

void StaticMapper::OnKeyFrames(const std::vector<KeyFrameRecord>& added,
                               const std::vector<KeyFramePose>& window) {
  std::vector<WindowKeyFrame> prepared;  // the expensive part, without the lock
  for (const KeyFrameRecord& keyframe : added) prepared.push_back(Prepare(keyframe));
  std::unordered_map<int, Eigen::Isometry3d> poses;
  for (const KeyFramePose& pose : window) poses.emplace(pose.id, pose.T_world_camera);
  const std::lock_guard<std::mutex> lock(mutex_);
  for (WindowKeyFrame& keyframe : prepared) window_.push_back(std::move(keyframe));
  std::deque<WindowKeyFrame> kept;
  for (WindowKeyFrame& keyframe : window_) {
    const auto pose = poses.find(keyframe.id);
    if (pose == poses.end()) {  // left Slam's window: its pose is final
      FuseForGood(std::move(keyframe));
      continue;
    }
    keyframe.T_world_camera = pose->second;
    kept.push_back(std::move(keyframe));
  }
  window_ = std::move(kept);
  ++revision_;
}

void StaticMapper::OnReset(ResetMode mode) {
  if (mode == ResetMode::kKeepPose) {  // the world frame goes on: the window is final
    FuseWindow();
    return;
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  voxels_.Clear();
  window_.clear();
  views_.clear();
  fused_.clear();
  stats_ = StaticMapStats();
  ++revision_;
}

void StaticMapper::FuseWindow() {
  const std::lock_guard<std::mutex> lock(mutex_);
  while (!window_.empty()) {
    WindowKeyFrame keyframe = std::move(window_.front());
    window_.pop_front();
    FuseForGood(std::move(keyframe));
  }
  ++revision_;
}

void StaticMapper::FuseForGood(WindowKeyFrame keyframe) {
  keyframe.view.set_pose(keyframe.T_world_camera);
  ColouredCloud points;
  if (config_.free_space_check) {
    // Only voxels hit within the last free_space_keyframes keyframes: drift between keyframes
    // far apart in time would make static surfaces look seen through.
    stats_.carved_voxels +=
        voxels_.Carve(keyframe.view, tolerance_, keyframe.id - config_.free_space_keyframes);
    points = CheckedPoints(keyframe);
    stats_.transient_points += keyframe.points_camera.size() - points.size();
  } else {
    const Eigen::Isometry3f T = keyframe.T_world_camera.cast<float>();
    for (const ColouredPoint& point : keyframe.points_camera) {
      points.push_back(Transformed(T, point));
    }
  }
  for (const ColouredPoint& point : points) voxels_.Add(point, keyframe.id);
  KeepFused(keyframe.id, keyframe.T_world_camera, points);
  const Eigen::Vector3f centre = keyframe.T_world_camera.translation().cast<float>();
  stats_.cropped_voxels += voxels_.Crop(centre, config_.extent_m);
  ++stats_.fused_keyframes;
  if (config_.free_space_check) {
    views_.push_back(std::move(keyframe.view));
    while (static_cast<int>(views_.size()) > config_.free_space_keyframes) views_.pop_front();
  }
}

void StaticMapper::KeepFused(int id, const Eigen::Isometry3d& T_world_camera,
                             const ColouredCloud& points_world) {
  FusedKeyFrame fused{id, T_world_camera, {}};
  const Eigen::Isometry3f T_camera_world = T_world_camera.inverse().cast<float>();
  fused.points_camera.reserve(points_world.size());
  for (const ColouredPoint& point : points_world) {
    fused.points_camera.push_back(Transformed(T_camera_world, point));
  }
  fused_.push_back(std::move(fused));
  while (fused_.size() > max_fused_kept_) fused_.pop_front();
}

void StaticMapper::OnCorrection(const std::vector<KeyFramePose>& keyframes) {
  std::unordered_map<int, Eigen::Isometry3d> poses;
  for (const KeyFramePose& pose : keyframes) poses.emplace(pose.id, pose.T_world_camera);
  const std::lock_guard<std::mutex> lock(mutex_);
  for (WindowKeyFrame& keyframe : window_) {
    const auto pose = poses.find(keyframe.id);
    if (pose != poses.end()) keyframe.T_world_camera = pose->second;
  }
  // Points whose voxels were carved (seen through later) or cropped since stay out.
  for (FusedKeyFrame& fused : fused_) {
    const Eigen::Isometry3f T_old = fused.T_world_camera.cast<float>();
    ColouredCloud& points = fused.points_camera;
    points.erase(std::remove_if(points.begin(), points.end(),
                                [&](const ColouredPoint& point) {
                                  return !voxels_.Contains(voxels_.KeyOf(T_old * point.p));
                                }),
                 points.end());
  }
  // The fused keyframes in the correction move with it; one the map erased moves as
  // KeyFrameMotion says (with the nearest older one in it).
  KeyFrameMotion motion;
  for (const FusedKeyFrame& fused : fused_) {
    const auto pose = poses.find(fused.id);
    if (pose != poses.end()) motion.Add(fused.id, pose->second, fused.T_world_camera);
  }
  voxels_.Clear();
  for (FusedKeyFrame& fused : fused_) {
    if (!motion.empty()) fused.T_world_camera = motion.For(fused.id) * fused.T_world_camera;
    const Eigen::Isometry3f T = fused.T_world_camera.cast<float>();
    for (const ColouredPoint& point : fused.points_camera) {
      voxels_.Add(Transformed(T, point), fused.id);
    }
  }
  if (!fused_.empty()) {
    const Eigen::Vector3f centre = fused_.back().T_world_camera.translation().cast<float>();
    stats_.cropped_voxels += voxels_.Crop(centre, config_.extent_m);
  }
  views_.clear();  // their poses are the old ones: the next keyframes' checks start afresh
  ++stats_.corrections;
  ++revision_;
}

ColouredCloud StaticMapper::CheckedPoints(const WindowKeyFrame& keyframe) {
  const Eigen::Isometry3f T = keyframe.T_world_camera.cast<float>();
  ColouredCloud kept;
  kept.reserve(keyframe.points_camera.size());
  for (const ColouredPoint& point : keyframe.points_camera) {
    const ColouredPoint world = Transformed(T, point);
    int hits = 1, misses = 0;  // its own keyframe saw it
    for (const DepthView& view : views_) {
      const Visibility vote = view.Vote(world.p, tolerance_);
      hits += vote == Visibility::kSupport;
      misses += vote == Visibility::kSeeThrough;
    }
    if (!tolerance_.Transient(misses, hits)) kept.push_back(world);
  }
  return kept;
}

ColouredCloud StaticMapper::Cloud() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  ColouredCloud cloud = voxels_.Points();
  VoxelMap pending(config_.voxel_size_m);  // window points where the fused map has none
  for (const WindowKeyFrame& keyframe : window_) {
    const Eigen::Isometry3f T = keyframe.T_world_camera.cast<float>();
    for (const ColouredPoint& point : keyframe.points_camera) {
      const ColouredPoint world = Transformed(T, point);
      if (!voxels_.Contains(voxels_.KeyOf(world.p))) pending.Add(world, keyframe.id);
    }
  }
  const ColouredCloud window_points = pending.Points();
  cloud.insert(cloud.end(), window_points.begin(), window_points.end());
  return cloud;
}

StaticMapRays StaticMapper::Rays() const {
  StaticMapRays rays;
  const std::lock_guard<std::mutex> lock(mutex_);
  for (const ColouredPoint& point : voxels_.Points()) rays.points_world.push_back(point.p);
  const auto add_view = [&](const Eigen::Isometry3d& T_world_camera, const ColouredCloud& points) {
    GridView view;
    view.camera_world = T_world_camera.translation();
    const Eigen::Isometry3f T = T_world_camera.cast<float>();
    view.points_world.reserve(points.size());
    for (const ColouredPoint& point : points) view.points_world.push_back(T * point.p);
    rays.views.push_back(std::move(view));
  };
  for (const FusedKeyFrame& keyframe : fused_)
    add_view(keyframe.T_world_camera, keyframe.points_camera);
  for (const WindowKeyFrame& keyframe : window_)
    add_view(keyframe.T_world_camera, keyframe.points_camera);
  return rays;
}

OccupancyGrid GridOf(const StaticMapRays& rays, const Eigen::Vector3d& up_world,
                     const Config& config) {
  const double cell_size_m =
      config.grid.cell_size_m > 0.0 ? config.grid.cell_size_m : config.map.voxel_size_m;
  return BuildOccupancyGrid(rays.points_world, rays.views, Eigen::Isometry3d::Identity(), up_world,
                            cell_size_m, config.grid, ViewVoteTolerance::From(config));
}

StaticMapStats StaticMapper::stats() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  StaticMapStats stats = stats_;
  stats.voxels = voxels_.size();
  stats.window_keyframes = static_cast<int>(window_.size());
  return stats;
}

uint64_t StaticMapper::revision() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return revision_;
}

}  // namespace dslam
