#pragma once
// dslam_run_dataset --save-keyframe-map / --load-keyframe-map: the run's final keyframe map saved
// as a keyframe map file (map_file/keyframe_map_file.h) with the camera, the identity of the
// run's vocabulary (--vocabulary, default the committed one) and the colour and depth images of
// every keyframe still in the map at the end (KeyFrameImageKeeper); and the run started in a
// loaded keyframe map (StartInKeyFrameMap: no pose until it localises, a new map after
// --localise-timeout-s), extended or, with --localisation-only, left as loaded: the saved map is
// then the loaded file unchanged. A file that cannot be read or does not fit the run is refused
// with the reason and the run maps from scratch (--localisation-only has no effect then).

#include <memory>
#include <string>
#include <vector>

#include "dslam/backend/slam.h"
#include "dslam/eval/json_writer.h"
#include "dslam/map_file/keyframe_map_session.h"
#include "dslam/place_recognition/vocabulary.h"

namespace dslam {
namespace tools {

/// Keeps the keyframes' images during the run and saves the map at its end; loads one at its
/// start.
class KeyFrameMapOutput {
 public:
  /// `save_path` empty: nothing is kept or saved. `vocabulary` (the run's; may be null when
  /// neither saving nor loading) gives the saved identity and the loaded map's places.
  KeyFrameMapOutput(const std::string& save_path, std::shared_ptr<const Vocabulary> vocabulary);

  /// The image keeper, for Slam's constructor (empty when no map is saved).
  std::vector<std::shared_ptr<KeyFrameObserver>> Observers() const;
  /// Gives the image keeper the Slam whose map it follows; call before the first frame.
  void Attach(const Slam* slam);

  /// Starts `slam` in the keyframe map file at `path` (nothing when empty); `camera` is the
  /// dataset's, `timeout_s` [s] the localisation timeout, `use` what the run may do with the map.
  /// A file that cannot be read or does not fit is reported on stderr and `slam` starts from
  /// scratch. Call after Attach, before the first frame.
  void Load(const std::string& path, std::shared_ptr<const PinholeCamera> camera, double timeout_s,
            LoadedMapUse use, Slam* slam);
  /// Saves `slam`'s map with `camera` and the kept images, or, when the run localised only in a
  /// loaded map, that map's file as it was loaded; call after Slam::WaitForBackEnd. Throws
  /// std::runtime_error when the file cannot be written.
  void Save(const Slam& slam, const PinholeCamera& camera);
  /// One line each for the loaded and the saved map (nothing for neither).
  void Print() const;
  /// Adds keyframe_map_loaded (true, false: refused, absent: none given) and, with it,
  /// localisation_only (true: the run localised only in the loaded map, which stayed as loaded).
  void AddTo(JsonObject* json) const;

 private:
  std::string save_path_, load_path_;
  std::shared_ptr<const Vocabulary> vocabulary_;
  std::shared_ptr<KeyFrameImageKeeper> keeper_;
  std::string load_problem_;        ///< why the loaded file was refused; "" when it was not
  bool localisation_only_ = false;  ///< the run localises only in the loaded map
  /// The loaded file when the run localises only in it and a map is to be saved (saved as it
  /// is); null otherwise.
  std::shared_ptr<const KeyFrameMapFile> localisation_map_;
  size_t loaded_keyframes_ = 0, loaded_points_ = 0;
  size_t keyframes_ = 0, points_ = 0, images_ = 0, bytes_ = 0;
};

}  // namespace tools
}  // namespace dslam
