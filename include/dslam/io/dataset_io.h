#pragma once
// Reading TUM RGB-D layout folders: rgb.txt, depth.txt, groundtruth.txt, rgb/ and depth/ PNGs, and
// the package's camera.yaml (intrinsics, distortion, depth_scale, groundtruth_correction).

#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dslam/core/camera.h"
#include "dslam/core/features_config.h"
#include "dslam/core/rgbd_frame.h"

namespace dslam {

/// How a dataset's ground truth relates to the colour camera (see BonnMarkerToCamera()).
enum class GroundTruthCorrection { kNone, kBonn };

/// Contents of a camera.yaml file.
struct CameraYaml {
  std::shared_ptr<const PinholeCamera> camera;  ///< intrinsics and distortion of the colour camera
  double depth_scale = 5000.0;  ///< depth PNG units per metre (TUM/Bonn: 5000), in [1, 1e6]
  GroundTruthCorrection groundtruth_correction = GroundTruthCorrection::kNone;
  /// The depth sensor's noise when the file states it (keys depth_sigma_d_quadratic [1/m] and
  /// depth_sigma_d_constant_m [m], both or neither, each in [0, 0.1]): sigma_d = a d^2 + b of one
  /// measurement, independent from pixel to pixel and frame to frame. dslam_synth writes it for
  /// its Gaussian depth noise; real cameras leave it out (the defaults of depth_noise model them).
  std::optional<double> depth_sigma_d_quadratic;   ///< [1/m] a
  std::optional<double> depth_sigma_d_constant_m;  ///< [m] b
};

/// Reads camera.yaml (keys width height fx fy cx cy, optional k1 k2 p1 p2 k3 depth_scale
/// groundtruth_correction none|bonn, depth_sigma_d_quadratic and depth_sigma_d_constant_m).
/// Throws std::runtime_error naming the file and the key.
CameraYaml LoadCameraYaml(const std::string& path);

/// Same as LoadCameraYaml, from the file's text; `name` (the file's name) starts each message.
CameraYaml ParseCameraYaml(const std::string& yaml_text, const std::string& name);

/// The camera.yaml a dataset run reads: `camera_yaml_path`, or the folder's when that is empty.
std::string CameraYamlPath(const std::string& folder, const std::string& camera_yaml_path);

/// Sets depth_noise.sigma_d_quadratic and sigma_d_constant_m to the noise `camera` states;
/// leaves `depth_noise` as it is when the file states none. Returns whether it set them.
bool UseCameraDepthNoise(const CameraYaml& camera, DepthNoiseConfig* depth_noise);

/// One line of rgb.txt / depth.txt / mask.txt: a stamp and a path relative to the folder.
struct StampedFile {
  double stamp_s = 0.0;  ///< [s]
  std::string path;      ///< relative to the dataset folder
};

/// Reads a TUM file list ("timestamp filename" lines, '#' comments). Throws on a malformed line.
std::vector<StampedFile> ReadFileList(const std::string& path);

/// Same as ReadFileList, from a stream; `name` (the file's name) starts each message.
std::vector<StampedFile> ParseFileList(std::istream& in, const std::string& name);

/// A colour image associated with its nearest depth image.
struct AssociatedPair {
  StampedFile colour;
  StampedFile depth;
};

/// Associates each colour stamp with the nearest depth stamp within `max_dt_s`; each depth image
/// is used at most once (greedy by smallest time difference, as TUM's associate.py). Sorted by
/// colour stamp. Colour frames without a partner are left out.
std::vector<AssociatedPair> AssociateByStamp(const std::vector<StampedFile>& colour,
                                             const std::vector<StampedFile>& depth,
                                             double max_dt_s);

/// A TUM-layout folder opened for sequential reading.
class TumDataset {
 public:
  /// Opens `folder`; camera.yaml is read from `camera_yaml_path`, or from the folder when empty.
  TumDataset(const std::string& folder, const std::string& camera_yaml_path,
             double association_max_dt_s);

  size_t size() const { return pairs_.size(); }  ///< number of associated colour/depth pairs
  const std::vector<AssociatedPair>& pairs() const { return pairs_; }
  const CameraYaml& camera_yaml() const { return camera_yaml_; }
  const std::string& folder() const { return folder_; }
  std::string groundtruth_path() const { return folder_ + "/groundtruth.txt"; }
  std::string rgb_list_path() const { return folder_ + "/rgb.txt"; }

  /// Loads pair `index`: colour as BGR, depth in metres. Throws std::runtime_error on bad files,
  /// and before decoding a colour file that is not PNG or JPEG, a depth file that is not PNG, or
  /// a PNG whose header declares a size beyond dslam/core/image_limits.h (CheckImageFile).
  RgbdFrame LoadFrame(size_t index) const;

 private:
  std::string folder_;
  CameraYaml camera_yaml_;
  std::vector<AssociatedPair> pairs_;
};

}  // namespace dslam
