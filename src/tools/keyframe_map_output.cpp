#include "keyframe_map_output.h"

#include <cstdio>
#include <filesystem>

namespace dslam {
namespace tools {

KeyFrameMapOutput::KeyFrameMapOutput(const std::string& save_path,
                                     std::shared_ptr<const Vocabulary> vocabulary)
    : save_path_(save_path), vocabulary_(std::move(vocabulary)) {
  if (!save_path_.empty()) keeper_ = std::make_shared<KeyFrameImageKeeper>();
}

std::vector<std::shared_ptr<KeyFrameObserver>> KeyFrameMapOutput::Observers() const {
  if (!keeper_) return {};
  return {keeper_};
}

void KeyFrameMapOutput::Attach(const Slam* slam) {
  if (keeper_) keeper_->Attach(slam);
}

void KeyFrameMapOutput::Load(const std::string& path, std::shared_ptr<const PinholeCamera> camera,
                             double timeout_s, LoadedMapUse use, Slam* slam) {
  load_path_ = path;
  if (path.empty()) return;
  const bool only = use == LoadedMapUse::kLocalisationOnly;
  try {
    KeyFrameMapFile file = LoadKeyFrameMap(path);
    const std::string warning = KeyFrameMapWarning(file);
    if (!warning.empty()) {
      std::fprintf(stderr, "dslam_run_dataset: keyframe map %s: %s\n", path.c_str(),
                   warning.c_str());
    }
    loaded_keyframes_ = file.contents.keyframes.size();
    loaded_points_ = file.contents.points.size();
    if (only && !save_path_.empty()) {  // saved as loaded: a copy, images included
      localisation_map_ = std::make_shared<const KeyFrameMapFile>(file);
    }
    load_problem_ = StartInKeyFrameMap(std::move(file), camera, vocabulary_, timeout_s, slam, use);
    localisation_only_ = only && load_problem_.empty();
    if (!localisation_only_) localisation_map_.reset();
  } catch (const KeyFrameMapError& e) {
    load_problem_ = e.what();
  }
  if (!load_problem_.empty()) {
    std::fprintf(stderr, "dslam_run_dataset: keyframe map %s refused: %s; mapping from scratch%s\n",
                 path.c_str(), load_problem_.c_str(),
                 only ? " (--localisation-only has no effect)" : "");
  }
  slam->WaitForBackEnd();  // the observers have the loaded keyframes before the first frame
}

void KeyFrameMapOutput::Save(const Slam& slam, const PinholeCamera& camera) {
  if (save_path_.empty()) return;
  const KeyFrameMapFile file =
      localisation_map_ ? *localisation_map_
                        : KeyFrameMapOf(slam, camera, vocabulary_->identity(), keeper_.get());
  SaveKeyFrameMap(save_path_, file, PreviousFile::kKeep);  // as the node's save on exit
  keyframes_ = file.contents.keyframes.size();
  points_ = file.contents.points.size();
  images_ = file.images.size();
  bytes_ = std::filesystem::file_size(save_path_);
}

void KeyFrameMapOutput::Print() const {
  if (!load_path_.empty() && load_problem_.empty()) {
    std::printf("keyframe map loaded: %zu keyframes, %zu points <- %s\n", loaded_keyframes_,
                loaded_points_, load_path_.c_str());
  }
  if (save_path_.empty()) return;
  std::printf(
      "keyframe map%s: %zu keyframes, %zu points, images of %zu keyframes, %zu bytes -> %s\n",
      localisation_only_ ? " (localisation only: the loaded map unchanged)" : "", keyframes_,
      points_, images_, bytes_, save_path_.c_str());
}

void KeyFrameMapOutput::AddTo(JsonObject* json) const {
  if (load_path_.empty()) return;
  json->AddBool("keyframe_map_loaded", load_problem_.empty());
  json->AddBool("localisation_only", localisation_only_);
}

}  // namespace tools
}  // namespace dslam
