#include "map_output.h"

#include <cstdio>

namespace dslam {
namespace tools {

MapOutput::MapOutput(const std::string& masked_path, const std::string& unmasked_path,
                     const std::string& grid_path, const std::string& octomap_path,
                     const Config& config)
    : masked_path_(masked_path),
      unmasked_path_(unmasked_path),
      grid_path_(grid_path),
      octomap_path_(octomap_path),
      config_(config) {
  if (!masked_path_.empty() || !grid_path_.empty() || !octomap_path_.empty()) {
    masked_ = std::make_shared<StaticMapper>(config);
  }
  if (!unmasked_path_.empty()) {
    Config baseline = config;
    baseline.map.dynamic_masks = false;
    baseline.map.free_space_check = false;
    unmasked_ = std::make_shared<StaticMapper>(baseline);
  }
}

std::vector<std::shared_ptr<KeyFrameObserver>> MapOutput::Observers() const {
  std::vector<std::shared_ptr<KeyFrameObserver>> observers;
  if (masked_) observers.push_back(masked_);
  if (unmasked_) observers.push_back(unmasked_);
  return observers;
}

void MapOutput::Write() {
  if (masked_) {
    masked_->FuseWindow();
    const ColouredCloud cloud = masked_->Cloud();
    if (!masked_path_.empty()) WritePcd(masked_path_, cloud);
    masked_points_ = cloud.size();
  }
  if (!grid_path_.empty() || !octomap_path_.empty()) {
    const StaticMapRays rays = masked_->Rays();
    if (!grid_path_.empty()) {
      // Up: grid.up_* in the first frame's optical frame, the trajectory's world.
      const GridConfig& grid = config_.grid;
      grid_ = GridOf(rays, Eigen::Vector3d(grid.up_x, grid.up_y, grid.up_z), config_);
      WriteMapServerFiles(grid_, grid_path_);
    }
    if (!octomap_path_.empty()) {
      octomap_ = WriteOctoMap(rays, config_.map.voxel_size_m, octomap_path_);
    }
  }
  if (unmasked_) {
    unmasked_->FuseWindow();
    const ColouredCloud cloud = unmasked_->Cloud();
    WritePcd(unmasked_path_, cloud);
    unmasked_points_ = cloud.size();
  }
}

void MapOutput::Print() const {
  if (!octomap_path_.empty()) {
    std::printf("octomap: %zu occupied and %zu free leaves of %.3f m -> %s\n",
                octomap_.occupied_leaves, octomap_.free_leaves, config_.map.voxel_size_m,
                octomap_path_.c_str());
  }
  if (!grid_path_.empty()) {
    std::printf("grid: %d x %d cells of %.3f m, %d occupied, %d free; floor %s -> %s\n",
                grid_.width, grid_.height, grid_.cell_size_m, grid_.Count(kCellOccupied),
                grid_.Count(kCellFree), FloorSource(grid_.floor), grid_path_.c_str());
  }
  if (!masked_path_.empty()) {
    const StaticMapStats stats = masked_->stats();
    std::printf(
        "map: %zu points from %d keyframes (%zu keyframe points seen through, %zu voxels "
        "carved, %zu cropped) -> %s\n",
        masked_points_, stats.fused_keyframes, stats.transient_points, stats.carved_voxels,
        stats.cropped_voxels, masked_path_.c_str());
  }
  if (unmasked_) {
    std::printf("map without masks and free-space check: %zu points from %d keyframes -> %s\n",
                unmasked_points_, unmasked_->stats().fused_keyframes, unmasked_path_.c_str());
  }
}

void MapOutput::AddTo(JsonObject* json) const {
  if (masked_) {
    const StaticMapStats stats = masked_->stats();
    json->AddInteger("map_points", static_cast<long>(masked_points_))
        .AddInteger("map_transient_points", static_cast<long>(stats.transient_points))
        .AddInteger("map_carved_voxels", static_cast<long>(stats.carved_voxels));
  }
  if (unmasked_) json->AddInteger("map_unmasked_points", static_cast<long>(unmasked_points_));
  if (!grid_path_.empty()) {
    json->AddInteger("grid_occupied_cells", grid_.Count(kCellOccupied))
        .AddInteger("grid_free_cells", grid_.Count(kCellFree))
        .AddInteger("grid_floor_from_plane", grid_.floor.from_plane ? 1 : 0);
  }
  if (!octomap_path_.empty()) {
    json->AddInteger("octomap_occupied_leaves", static_cast<long>(octomap_.occupied_leaves))
        .AddInteger("octomap_free_leaves", static_cast<long>(octomap_.free_leaves));
  }
}

}  // namespace tools
}  // namespace dslam
