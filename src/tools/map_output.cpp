#include "map_output.h"

#include <cstdio>

namespace dslam {
namespace tools {

MapOutput::MapOutput(const std::string& masked_path, const std::string& unmasked_path,
                     const Config& config)
    : masked_path_(masked_path), unmasked_path_(unmasked_path) {
  if (!masked_path_.empty()) masked_ = std::make_shared<StaticMapper>(config);
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
    WritePcd(masked_path_, cloud);
    masked_points_ = cloud.size();
  }
  if (unmasked_) {
    unmasked_->FuseWindow();
    const ColouredCloud cloud = unmasked_->Cloud();
    WritePcd(unmasked_path_, cloud);
    unmasked_points_ = cloud.size();
  }
}

void MapOutput::Print() const {
  if (masked_) {
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
}

}  // namespace tools
}  // namespace dslam
