#pragma once
// The keyframe map file: a keyframe map (tracking/map.h, MapContents) with the camera it was made
// with, the identity of the place-recognition vocabulary of the run (Vocabulary::identity(),
// place_recognition/vocabulary.h) and, optionally, each keyframe's colour and depth images, so
// that a later run can localise in the map, extend it and re-fuse its static map.
//
// File format, version 2. Integers little-endian (iN: two's complement), fN: IEEE-754 binary64
// bit patterns (core/binary_io.h), matrices row-major.
//   Header, 180 bytes (version 1: 128 bytes, without the settings at 128):
//     0  8 bytes  magic "DSLAMKFM"
//     8  u32      format version (kKeyFrameMapVersion)
//    12  u64      size of the whole file [bytes]
//    20  u64      checksum: 64-bit FNV-1a of every byte from offset 28 to the end of the file
//    28  u32 width, u32 height [px]; f64 fx, fy, cx, cy [px]; f64 k1, k2, p1, p2, k3 [-]
//   108  u64      vocabulary identity
//   116  u32 number of map points P, u32 number of keyframes K, u32 number of image pairs I
//   128  the settings of the run that made the map (KeyFrameMapSettings; not in version 1):
//        u32 features.num_levels; f64 features.scale_factor [-]; f64 depth_noise.pixel_sigma_px
//        [px], sigma_d_quadratic [1/m], sigma_d_constant_m [m], min_depth_m [m], max_depth_m [m]
//   Body, from offset 180 (version 1: 128):
//     P map points, ids ascending, each (MapPoint's fields but observing_keyframes, which a
//     loaded map recounts):
//       i64 id; f64 p_world[3] [m]; f64 cov_world[9] [m^2]; u8 descriptor length (0 or 32) and
//       that many descriptor bytes (a 1x32 CV_8U ORB descriptor, or none); i32 octave;
//       i32 created_feature; f64 reference_distance_m [m]; u8 flags (bit 0 marked, bit 1
//       candidate, the others 0); i32 created_frame, last_seen_frame, times_visible,
//       times_found, isolated_frames, static_streak, dynamic_frames.
//     K keyframes, ids ascending, each:
//       i32 id; i32 frame_index; f64 stamp_s [s]; f64 T_world_camera[12] (the 3x4 [R | t], t in
//       m); f64 information[36]; u8 weak_since_previous (0 or 1); u32 n, then n i64 point ids
//       (KeyFrame::points in order); f64 measurements.T_camera_world[12] (3x4 [R | t]); u32 m,
//       then m measurements, point ids ascending, each: i64 point id, f64 y_camera[3] [m],
//       f64 covariance[9] [m^2], f64 depth_mean_m [m], f64 depth_sigma_m [m].
//     I image pairs, keyframe ids ascending, each: i32 keyframe id; u32 c, then c bytes of a PNG
//       of the colour image (8-bit, 3 channels BGR or 1 grey, lossless); u32 d, then d bytes of
//       a 16-bit single-channel PNG of the depth in millimetres.
// Depth is stored as round(1000 d) for 0.0005 m <= d < 65.5355 m: a loaded depth differs from
// the saved one by at most 0.5 mm (plus float rounding); 0, NaN, infinite, negative and larger
// depths are stored and loaded as 0 (no measurement), and so are depths below 0.5 mm.

// The writer streams the file (peak memory: the map plus one record and one image's PNG) and
// the reader reads it twice as a stream, first for its size and checksum, then for its records
// (peak memory: the loaded map plus a read buffer).

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>

#include "dslam/core/atomic_file.h"
#include "dslam/core/camera.h"
#include "dslam/core/features_config.h"
#include "dslam/tracking/map.h"

namespace dslam {

struct Config;

/// The format version SaveKeyFrameMap writes (version 1 for a file without settings).
/// LoadKeyFrameMap reads versions 1 and 2.
constexpr std::uint32_t kKeyFrameMapVersion = 2;
/// Bytes of the version 2 header (file format above); the body starts here.
constexpr std::size_t kKeyFrameMapHeaderBytes = 180;
/// Bytes of the version 1 header.
constexpr std::size_t kKeyFrameMapV1HeaderBytes = 128;
/// Largest keyframe id and frame index a file may hold, so that a run continuing the map has
/// about 10^9 more keyframes and frames (at 30 Hz, over a year) before an int would overflow.
constexpr int kKeyFrameMapMaxIndex = (1 << 30) - 1;
/// Largest map point id a file may hold (the same headroom for the 64-bit PointId).
constexpr PointId kKeyFrameMapMaxPointId = (PointId{1} << 62) - 1;

/// The settings of the run that made a keyframe map that its contents depend on and that a run
/// using the map must share: the ORB pyramid of its points' descriptors and octaves, and the depth
/// noise model of its covariances (format version 2).
struct KeyFrameMapSettings {
  int orb_levels = 8;             ///< [-] features.num_levels, >= 1
  double orb_scale_factor = 1.2;  ///< [-] features.scale_factor, > 1
  DepthNoiseConfig depth_noise;   ///< depth_noise: pixel sigma > 0, the others >= 0, finite
};

/// The KeyFrameMapSettings of a run with `config`.
KeyFrameMapSettings KeyFrameMapSettingsOf(const Config& config);

/// One keyframe's images, as the frame it was made from had them (RgbdFrame, core/rgbd_frame.h).
struct KeyFrameImages {
  cv::Mat colour;   ///< CV_8UC3 BGR or CV_8UC1 grey, the camera's width x height
  cv::Mat depth_m;  ///< CV_32FC1 depth along the optical axis [m], 0 = no measurement
};

/// Everything a keyframe map file holds.
struct KeyFrameMapFile {
  PinholeCamera camera;  ///< the camera the keyframes were taken with
  /// Vocabulary::identity() of the vocabulary the map's place recognition uses (0: none).
  std::uint64_t vocabulary_identity = 0;
  /// Points and keyframes, each list by id ascending; poses in the map's world frame (the
  /// odometry world frame of the run that made it: its first camera's optical frame).
  MapContents contents;
  /// Images by KeyFrame::id, of keyframes in `contents` only; may be empty.
  std::map<int, KeyFrameImages> images;
  /// The settings the map was made with; none when it was loaded from a version 1 file (and then
  /// saved as version 1 again).
  std::optional<KeyFrameMapSettings> settings;
};

/// A keyframe map file that cannot be read: the message names the file (or the name given to
/// ParseKeyFrameMap) and says why (not a keyframe map, unsupported version, truncated, checksum
/// mismatch, invalid content).
class KeyFrameMapError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The file's bytes (format above; version 1 when `file` has no settings). Throws
/// std::invalid_argument when `file` breaks a rule the reader checks: point or keyframe ids
/// negative or not ascending, point ids above kKeyFrameMapMaxPointId, keyframe ids or frame
/// indices above kKeyFrameMapMaxIndex, a non-finite number, a pose whose rotation is not one
/// (|R^T R - I| > 1e-6 or det R <= 0), a point covariance or measurement covariance that is not
/// symmetric positive definite, a keyframe information that is neither zero (unknown) nor
/// symmetric positive definite, a depth_sigma_m not above 0, settings out of their range, a
/// descriptor that is neither empty nor 1x32 CV_8U, images of a keyframe not in the map or of
/// another type or size than the camera's. Symmetric: |A - A^T| <= 1e-6 |A| (Frobenius).
std::string SerialiseKeyFrameMap(const KeyFrameMapFile& file);

/// Streams the file (SerialiseKeyFrameMap's bytes) to a temporary file next to `path` and renames
/// it to `path` (WriteFileAtomically, core/binary_io.h: fsync of the file and its folder), so that
/// `path` holds the old file or the new one, complete, whenever the save stops. `previous`
/// PreviousFile::kKeep keeps a file already at `path` as `path` + ".prev". Throws
/// std::invalid_argument as SerialiseKeyFrameMap does (before any file is made),
/// std::runtime_error naming the file when writing fails.
void SaveKeyFrameMap(const std::string& path, const KeyFrameMapFile& file,
                     PreviousFile previous = PreviousFile::kReplace);

/// Reads a file SaveKeyFrameMap wrote (version 1 or 2) as a stream: its size and checksum first,
/// then its records. Throws KeyFrameMapError naming `path` when it cannot be opened or read, or
/// when ParseKeyFrameMap would refuse its bytes (with the same message). The contents satisfy
/// Map::FromContents (ids unique and not negative; keyframes may list points absent from the map,
/// which FromContents drops).
KeyFrameMapFile LoadKeyFrameMap(const std::string& path);

/// Parses the bytes of a keyframe map file (LoadKeyFrameMap's parser, and the fuzz harness's).
/// Throws KeyFrameMapError "<name>: <why>" for an empty input, another magic ("not a dslam
/// keyframe map"), a version other than 1 and 2 ("unsupported format version N"), fewer bytes than
/// the header gives ("truncated: expected X bytes, got Y"), more ("corrupt: ..."), a checksum
/// mismatch, or contents that break SerialiseKeyFrameMap's rules ("invalid content: ..."). Every
/// count is checked against the bytes left before anything of its size is allocated.
KeyFrameMapFile ParseKeyFrameMap(const std::string& bytes,
                                 const std::string& name = "keyframe map");

/// Whether a run with `camera`, the vocabulary of `vocabulary_identity` and `settings` can use
/// `file`: "" when its camera has the same size and its intrinsics and distortion are equal within
/// 1e-9 (relative, at least 1e-9 absolute), its vocabulary identity is the same and its settings
/// (when it has them: version 2) are equal (numbers within 1e-9 the same way); otherwise why
/// not, e.g. "recorded with another camera (640x480 fx 542.8 ...) than this run's (...)",
/// "recorded with vocabulary 723a8e39b1688a18 but this run uses 0123456789abcdef" or
/// "recorded with features.scale_factor 1.2 but this run uses 1.3".
std::string CheckCompatible(const KeyFrameMapFile& file, const PinholeCamera& camera,
                            std::uint64_t vocabulary_identity, const KeyFrameMapSettings& settings);

/// A warning for whoever loads `file`, "" when there is none: for a file without settings
/// (version 1), "format version 1: the ORB and depth noise settings the map was made with are
/// not in the file and cannot be checked against this run's".
std::string KeyFrameMapWarning(const KeyFrameMapFile& file);

}  // namespace dslam
