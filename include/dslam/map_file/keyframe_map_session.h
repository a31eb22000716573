#pragma once
// A keyframe map file in a running Slam: the images of the map's keyframes kept during the run
// (KeyFrameImageKeeper), the map taken for saving (KeyFrameMapOf), and a run started in a loaded
// map (StartInKeyFrameMap: the file checked against the run's camera and vocabulary, the tracker
// localising by place recognition, the loaded keyframes handed to the observers so that the
// static map re-fuses them and loop closing knows them). dslam_run_dataset and the node share it.

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "dslam/backend/keyframe_observer.h"
#include "dslam/backend/slam.h"
#include "dslam/map_file/keyframe_map_file.h"
#include "dslam/place_recognition/vocabulary.h"

namespace dslam {

/// Slam's keyframe observer that keeps the colour and depth images (shared, uncompressed: about
/// 2 MB per 640x480 keyframe) of the keyframes still in its map: after each delivery of new
/// keyframes, those the map erased are dropped. Thread-safe.
class KeyFrameImageKeeper : public KeyFrameObserver {
 public:
  /// The Slam whose map decides which images stay; call before its first frame.
  void Attach(const Slam* slam) { slam_ = slam; }
  void OnKeyFrames(const std::vector<KeyFrameRecord>& added,
                   const std::vector<KeyFramePose>& window) override;
  /// Nothing: the next delivery drops what left the map.
  void OnReset(ResetMode mode) override {}
  /// The kept images of the keyframes in `contents`.
  std::map<int, KeyFrameImages> ImagesOf(const MapContents& contents) const;

 private:
  const Slam* slam_ = nullptr;
  mutable std::mutex mutex_;  ///< guards images_; never held while calling Slam
  std::map<int, KeyFrameImages> images_;
};

/// `slam`'s keyframe map now (Map::Contents under Slam::ReadMap) with `camera`,
/// `vocabulary_identity`, the settings of `slam`'s config (KeyFrameMapSettingsOf) and the images
/// `keeper` (may be null: none) kept of its keyframes.
KeyFrameMapFile KeyFrameMapOf(const Slam& slam, const PinholeCamera& camera,
                              std::uint64_t vocabulary_identity, const KeyFrameImageKeeper* keeper);

/// The keyframes of `file` that have images, as records for keyframe observers, ids ascending:
/// the frame (its images, `camera`, the keyframe's stamp), the pose, and each point measured in
/// it (KeyFrame::measurements) that the map has, at the pixel its measurement projects to
/// (distorted), labelled by the point's marks.
std::vector<KeyFrameRecord> LoadedKeyFrameRecords(const KeyFrameMapFile& file,
                                                  std::shared_ptr<const PinholeCamera> camera);

/// Starts `slam` in the map of `file` when CheckCompatible(file, *camera,
/// vocabulary->identity(), KeyFrameMapSettingsOf(slam->config())) passes: Slam::StartInMap with
/// MapPlaces over `vocabulary`, timeout `localise_timeout_s` [s], LoadedKeyFrameRecords and `use`
/// (LoadedMapUse::kLocalisationOnly: the map stays as loaded; a save should then write `file`
/// itself). Returns "" then; otherwise why the file does not fit this run, and `slam` is unchanged.
/// Throws std::invalid_argument as StartInMap.
std::string StartInKeyFrameMap(KeyFrameMapFile file, std::shared_ptr<const PinholeCamera> camera,
                               std::shared_ptr<const Vocabulary> vocabulary,
                               double localise_timeout_s, Slam* slam,
                               LoadedMapUse use = LoadedMapUse::kExtend);

}  // namespace dslam
