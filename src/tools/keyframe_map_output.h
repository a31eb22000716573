#pragma once
// dslam_run_dataset --save-keyframe-map: the run's final keyframe map saved as a keyframe map
// file (map_file/keyframe_map_file.h) with the camera, the identity of the vocabulary given by
// --vocabulary (default: the committed one; the vocabulary loop closing uses when it is on, loaded
// for its identity alone when it is off) and the colour and depth images of every keyframe still
// in the map at the end. The images are kept (uncompressed, shared with the frames they came
// from: about 2 MB per keyframe at 640x480) for the keyframes of the map only: after each
// delivery of new keyframes those that left the map are dropped.

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "dslam/backend/slam.h"
#include "dslam/map_file/keyframe_map_file.h"

namespace dslam {
namespace tools {

/// Keeps the keyframes' images during the run and saves the map at its end.
class KeyFrameMapOutput {
 public:
  /// `path` empty: nothing is kept or saved. Otherwise loads the vocabulary at
  /// `vocabulary_path` (empty: DefaultVocabularyPath()) for its identity; throws
  /// std::runtime_error when it cannot.
  KeyFrameMapOutput(const std::string& path, const std::string& vocabulary_path);

  /// The image keeper, for Slam's constructor (empty when no map is saved).
  std::vector<std::shared_ptr<KeyFrameObserver>> Observers() const;
  /// Gives the image keeper the Slam whose map it follows; call before the first frame.
  void Attach(const Slam* slam);

  /// Saves `slam`'s map (Map::Contents), `camera`, the vocabulary identity and the kept images;
  /// call after Slam::WaitForBackEnd. Throws std::runtime_error when the file cannot be written.
  void Save(const Slam& slam, const PinholeCamera& camera);
  /// One line: keyframes, points, images, bytes and the path (nothing when not saved).
  void Print() const;

 private:
  class ImageKeeper;

  std::string path_;
  std::uint64_t vocabulary_identity_ = 0;
  std::shared_ptr<ImageKeeper> keeper_;
  size_t keyframes_ = 0, points_ = 0, images_ = 0, bytes_ = 0;
};

}  // namespace tools
}  // namespace dslam
