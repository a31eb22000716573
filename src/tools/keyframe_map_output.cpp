#include "keyframe_map_output.h"

#include <cstdio>
#include <filesystem>
#include <set>

#include "dslam/place_recognition/vocabulary.h"

namespace dslam {
namespace tools {

/// Slam's keyframe observer that keeps the images of the keyframes in its map.
class KeyFrameMapOutput::ImageKeeper : public KeyFrameObserver {
 public:
  void OnKeyFrames(const std::vector<KeyFrameRecord>& added,
                   const std::vector<KeyFramePose>& window) override {
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

  void OnReset(ResetMode mode) override {}  // the next delivery drops what left the map

  void Attach(const Slam* slam) { slam_ = slam; }

  /// The kept images of the keyframes in `contents`.
  std::map<int, KeyFrameImages> ImagesOf(const MapContents& contents) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::map<int, KeyFrameImages> images;
    for (const KeyFrame& keyframe : contents.keyframes) {
      const auto it = images_.find(keyframe.id);
      if (it != images_.end()) images.insert(*it);
    }
    return images;
  }

 private:
  const Slam* slam_ = nullptr;
  mutable std::mutex mutex_;
  std::map<int, KeyFrameImages> images_;
};

KeyFrameMapOutput::KeyFrameMapOutput(const std::string& path, const std::string& vocabulary_path)
    : path_(path) {
  if (path_.empty()) return;
  const std::string vocabulary =
      vocabulary_path.empty() ? DefaultVocabularyPath() : vocabulary_path;
  vocabulary_identity_ = Vocabulary::Load(vocabulary).identity();
  keeper_ = std::make_shared<ImageKeeper>();
}

std::vector<std::shared_ptr<KeyFrameObserver>> KeyFrameMapOutput::Observers() const {
  if (!keeper_) return {};
  return {keeper_};
}

void KeyFrameMapOutput::Attach(const Slam* slam) {
  if (keeper_) keeper_->Attach(slam);
}

void KeyFrameMapOutput::Save(const Slam& slam, const PinholeCamera& camera) {
  if (path_.empty()) return;
  KeyFrameMapFile file{camera, vocabulary_identity_, {}, {}};
  slam.ReadMap([&](const Map& map) { file.contents = map.Contents(); });
  file.images = keeper_->ImagesOf(file.contents);
  SaveKeyFrameMap(path_, file);
  keyframes_ = file.contents.keyframes.size();
  points_ = file.contents.points.size();
  images_ = file.images.size();
  bytes_ = std::filesystem::file_size(path_);
}

void KeyFrameMapOutput::Print() const {
  if (path_.empty()) return;
  std::printf("keyframe map: %zu keyframes, %zu points, images of %zu keyframes, %zu bytes -> %s\n",
              keyframes_, points_, images_, bytes_, path_.c_str());
}

}  // namespace tools
}  // namespace dslam
