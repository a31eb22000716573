#include "dslam/map_file/keyframe_map_session.h"

#include <set>

#include "dslam/loop_closing/map_places.h"

namespace dslam {

void KeyFrameImageKeeper::OnKeyFrames(const std::vector<KeyFrameRecord>& added,
                                      const std::vector<KeyFramePose>& /*window*/) {
  if (added.empty()) return;
  std::set<int> in_map;
  if (slam_ != nullptr) {
    slam_->ReadMap([&](const Map& map) {
      for (const KeyFrame* keyframe : map.AllKeyFrames()) in_map.insert(keyframe->id);
    });
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  for (const KeyFrameRecord& record : added) {
    images_[record.id] = KeyFrameImages{record.frame.colour, record.frame.depth_m};
  }
  for (auto it = images_.begin(); it != images_.end();) {
    it = in_map.count(it->first) == 0 ? images_.erase(it) : std::next(it);
  }
}

std::map<int, KeyFrameImages> KeyFrameImageKeeper::ImagesOf(const MapContents& contents) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::map<int, KeyFrameImages> images;
  for (const KeyFrame& keyframe : contents.keyframes) {
    const auto it = images_.find(keyframe.id);
    if (it != images_.end()) images.insert(*it);
  }
  return images;
}

KeyFrameMapFile KeyFrameMapOf(const Slam& slam, const PinholeCamera& camera,
                              std::uint64_t vocabulary_identity,
                              const KeyFrameImageKeeper* keeper) {
  KeyFrameMapFile file{camera, vocabulary_identity, {}, {}, KeyFrameMapSettingsOf(slam.config())};
  slam.ReadMap([&](const Map& map) { file.contents = map.Contents(); });
  if (keeper != nullptr) file.images = keeper->ImagesOf(file.contents);
  return file;
}

std::vector<KeyFrameRecord> LoadedKeyFrameRecords(const KeyFrameMapFile& file,
                                                  std::shared_ptr<const PinholeCamera> camera) {
  std::map<PointId, const MapPoint*> points;
  for (const MapPoint& point : file.contents.points) points[point.id] = &point;
  std::vector<KeyFrameRecord> records;
  for (const KeyFrame& keyframe : file.contents.keyframes) {
    const auto images = file.images.find(keyframe.id);
    if (images == file.images.end()) continue;
    KeyFrameRecord record;
    record.id = keyframe.id;
    record.frame.stamp_s = keyframe.stamp_s;
    record.frame.colour = images->second.colour;
    record.frame.depth_m = images->second.depth_m;
    record.frame.camera = camera;
    record.T_world_camera = keyframe.T_world_camera;
    for (const auto& [id, measurement] : keyframe.measurements.by_point) {
      const auto point = points.find(id);
      if (point == points.end() || measurement.y_camera.z() <= 0.0) continue;
      ObservedPoint observed;
      observed.id = id;
      observed.uv_raw = camera->Distort(camera->Project(measurement.y_camera));
      observed.p_world = point->second->p_world;
      observed.is_static = point->second->marked;
      observed.is_candidate = point->second->IsCandidate();
      record.points.push_back(observed);
    }
    records.push_back(std::move(record));
  }
  return records;
}

std::string StartInKeyFrameMap(KeyFrameMapFile file, std::shared_ptr<const PinholeCamera> camera,
                               std::shared_ptr<const Vocabulary> vocabulary,
                               double localise_timeout_s, Slam* slam, LoadedMapUse use) {
  const std::string why =
      CheckCompatible(file, *camera, vocabulary->identity(), KeyFrameMapSettingsOf(slam->config()));
  if (!why.empty()) return why;
  std::vector<KeyFrameRecord> records = LoadedKeyFrameRecords(file, camera);
  slam->StartInMap(Map::FromContents(std::move(file.contents)),
                   std::make_shared<MapPlaces>(std::move(vocabulary)), localise_timeout_s,
                   std::move(records), use);
  return "";
}

}  // namespace dslam
