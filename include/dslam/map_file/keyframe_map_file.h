#pragma once
// The keyframe map file: a keyframe map (tracking/map.h, MapContents) with the camera it was made
// with, the identity of the place-recognition vocabulary of the run (Vocabulary::identity(),
// place_recognition/vocabulary.h) and, optionally, each keyframe's colour and depth images, so
// that a later run can localise in the map, extend it and re-fuse its static map.
//
// File format, version 1. Integers little-endian (iN: two's complement), fN: IEEE-754 binary64
// bit patterns (core/binary_io.h), matrices row-major.
//   Header, 128 bytes:
//     0  8 bytes  magic "DSLAMKFM"
//     8  u32      format version (kKeyFrameMapVersion)
//    12  u64      size of the whole file [bytes]
//    20  u64      checksum: 64-bit FNV-1a of every byte from offset 28 to the end of the file
//    28  u32 width, u32 height [px]; f64 fx, fy, cx, cy [px]; f64 k1, k2, p1, p2, k3 [-]
//   108  u64      vocabulary identity
//   116  u32 number of map points P, u32 number of keyframes K, u32 number of image pairs I
//   Body, from offset 128:
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

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>

#include "dslam/core/camera.h"
#include "dslam/tracking/map.h"

namespace dslam {

/// The format version SaveKeyFrameMap writes and the only one LoadKeyFrameMap reads.
constexpr std::uint32_t kKeyFrameMapVersion = 1;
/// Bytes of the header (file format above); the body starts here.
constexpr std::size_t kKeyFrameMapHeaderBytes = 128;

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
};

/// A keyframe map file that cannot be read: the message names the file (or the name given to
/// ParseKeyFrameMap) and says why (not a keyframe map, unsupported version, truncated, checksum
/// mismatch, invalid content).
class KeyFrameMapError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The file's bytes (format above). Throws std::invalid_argument when `file` breaks a rule the
/// reader checks: point or keyframe ids negative or not ascending, a non-finite number, a pose
/// whose rotation is not one (|R^T R - I| > 1e-6 or det R <= 0), a descriptor that is neither
/// empty nor 1x32 CV_8U, images of a keyframe not in the map or of another type or size than
/// the camera's.
std::string SerialiseKeyFrameMap(const KeyFrameMapFile& file);

/// Writes SerialiseKeyFrameMap(file) to `path` + ".tmp-<pid>" and renames it to `path`, so that
/// a failed save leaves an older file at `path` as it was. Throws std::invalid_argument as
/// SerialiseKeyFrameMap does, std::runtime_error naming the file when writing fails.
void SaveKeyFrameMap(const std::string& path, const KeyFrameMapFile& file);

/// Reads a file SaveKeyFrameMap wrote. Throws KeyFrameMapError naming `path` when it cannot be
/// opened or ParseKeyFrameMap refuses its bytes. The contents satisfy Map::FromContents
/// (ids unique and not negative; keyframes may list points absent from the map, which
/// FromContents drops).
KeyFrameMapFile LoadKeyFrameMap(const std::string& path);

/// Parses the bytes of a keyframe map file (LoadKeyFrameMap's parser, and the fuzz harness's).
/// Throws KeyFrameMapError "<name>: <why>" for an empty input, another magic ("not a dslam
/// keyframe map"), another version ("unsupported format version N"), fewer bytes than the header
/// gives ("truncated: expected X bytes, got Y"), more ("corrupt: ..."), a checksum mismatch, or
/// contents that break SerialiseKeyFrameMap's rules ("invalid content: ..."). Every count is
/// checked against the bytes left before anything of its size is allocated.
KeyFrameMapFile ParseKeyFrameMap(const std::string& bytes,
                                 const std::string& name = "keyframe map");

/// Whether a run with `camera` and the vocabulary of `vocabulary_identity` can use `file`: ""
/// when its camera has the same size and its intrinsics and distortion are equal within 1e-9
/// (relative, at least 1e-9 absolute) and its vocabulary identity is the same; otherwise why
/// not, e.g. "recorded with another camera (640x480 fx 542.8 ...) than this run's (...)" or
/// "recorded with vocabulary 723a8e39b1688a18 but this run uses 0123456789abcdef".
std::string CheckCompatible(const KeyFrameMapFile& file, const PinholeCamera& camera,
                            std::uint64_t vocabulary_identity);

}  // namespace dslam
