// The keyframe map file's reader: ParseKeyFrameMap and LoadKeyFrameMap (format in
// dslam/map_file/keyframe_map_file.h). The header is checked first (magic, version, size,
// checksum), then the body is read with every count bounded by the bytes left, then the
// contents are checked against the rules the writer keeps (CheckContents).
#include <cstring>
#include <optional>

#include "dslam/core/binary_io.h"
#include "keyframe_map_internal.h"

namespace dslam {
namespace map_file {
namespace {

[[noreturn]] void Fail(const std::string& name, const std::string& why) {
  throw KeyFrameMapError(name + ": " + why);
}

// Magic, version, file size and checksum of `bytes`; throws when one does not hold.
void CheckHeader(const std::string& bytes, const std::string& name) {
  if (bytes.empty()) Fail(name, "empty file, not a dslam keyframe map");
  const std::size_t compared = std::min(bytes.size(), sizeof(kMagic));
  if (std::memcmp(bytes.data(), kMagic, compared) != 0) {
    Fail(name, "not a dslam keyframe map (its first bytes are not the magic \"DSLAMKFM\")");
  }
  const std::string got = ", got " + std::to_string(bytes.size());
  if (bytes.size() < 12) Fail(name, "truncated: expected at least 12 bytes" + got);
  const std::uint64_t version = GetLittleEndian(bytes, 8, 4);
  if (version != kKeyFrameMapVersion) {
    Fail(name, "unsupported format version " + std::to_string(version) + " (this build reads " +
                   std::to_string(kKeyFrameMapVersion) + ")");
  }
  if (bytes.size() < kKeyFrameMapHeaderBytes) {
    Fail(name, "truncated: expected at least " + std::to_string(kKeyFrameMapHeaderBytes) +
                   " bytes (the header)" + got);
  }
  const std::uint64_t size = GetLittleEndian(bytes, 12, 8);
  if (bytes.size() < size) {
    Fail(name, "truncated: expected " + std::to_string(size) + " bytes" + got);
  }
  if (bytes.size() > size) {
    Fail(name, "corrupt: " + std::to_string(bytes.size()) + " bytes, the header gives " +
                   std::to_string(size));
  }
  const std::uint64_t checksum = GetLittleEndian(bytes, 20, 8);
  if (Fnv1a64(bytes.data() + kChecksumFrom, bytes.size() - kChecksumFrom) != checksum) {
    Fail(name, "checksum mismatch: the file is corrupt");
  }
}

PinholeCamera ReadCamera(ByteReader* in, const std::string& name) {
  const std::uint32_t width = in->U32("camera");
  const std::uint32_t height = in->U32("camera");
  double v[9];
  in->F64s(v, 9, "camera");
  try {
    return PinholeCamera(static_cast<int>(std::min<std::uint32_t>(width, 1u << 30)),
                         static_cast<int>(std::min<std::uint32_t>(height, 1u << 30)), v[0], v[1],
                         v[2], v[3], Distortion{v[4], v[5], v[6], v[7], v[8]});
  } catch (const std::invalid_argument& e) {
    Fail(name, std::string("invalid content: camera: ") + e.what());
  }
}

template <typename Matrix>
void ReadMatrix(ByteReader* in, Matrix* m, const char* what) {
  for (int r = 0; r < m->rows(); ++r) {
    for (int c = 0; c < m->cols(); ++c) (*m)(r, c) = in->F64(what);
  }
}

MapPoint ReadPoint(ByteReader* in, const std::string& name) {
  MapPoint p;
  p.id = in->I64("a map point");
  ReadMatrix(in, &p.p_world, "a map point");
  ReadMatrix(in, &p.cov_world, "a map point");
  const std::uint8_t length = in->U8("a map point");
  if (length != 0 && length != kDescriptorBytes) {
    Fail(name, "invalid content: map point " + std::to_string(p.id) + " has a descriptor of " +
                   std::to_string(length) + " bytes (0 or 32)");
  }
  if (length > 0) {
    const std::string d = in->Bytes(length, "a descriptor");
    p.descriptor = cv::Mat(1, kDescriptorBytes, CV_8U);
    std::memcpy(p.descriptor.data, d.data(), d.size());
  }
  p.octave = in->I32("a map point");
  p.created_feature = in->I32("a map point");
  p.reference_distance_m = in->F64("a map point");
  const std::uint8_t flags = in->U8("a map point");
  if (flags > 3) {
    Fail(name, "invalid content: map point " + std::to_string(p.id) + " has flags " +
                   std::to_string(flags) + " (bits 0 and 1 only)");
  }
  p.marked = (flags & 1) != 0;
  p.candidate = (flags & 2) != 0;
  for (int* v : {&p.created_frame, &p.last_seen_frame, &p.times_visible, &p.times_found,
                 &p.isolated_frames, &p.static_streak, &p.dynamic_frames}) {
    *v = in->I32("a map point");
  }
  return p;
}

void ReadMeasurements(ByteReader* in, int keyframe, FrameMeasurements* out,
                      const std::string& name) {
  out->T_camera_world = ReadPose(in, "measurements");
  const std::uint32_t n = in->Count(kMeasurementBytes, "measurements");
  out->by_point.reserve(n);
  std::optional<PointId> previous;
  for (std::uint32_t i = 0; i < n; ++i) {
    const PointId id = in->I64("a measurement");
    if (previous && id <= *previous) {
      Fail(name, "invalid content: keyframe " + std::to_string(keyframe) +
                     " lists measurements of point " + std::to_string(id) + " out of order");
    }
    previous = id;
    PointMeasurement m;
    ReadMatrix(in, &m.y_camera, "a measurement");
    ReadMatrix(in, &m.covariance, "a measurement");
    m.depth_mean_m = in->F64("a measurement");
    m.depth_sigma_m = in->F64("a measurement");
    out->by_point.emplace(id, m);
  }
}

KeyFrame ReadKeyFrame(ByteReader* in, const std::string& name) {
  KeyFrame k;
  k.id = in->I32("a keyframe");
  k.frame_index = in->I32("a keyframe");
  k.stamp_s = in->F64("a keyframe");
  k.T_world_camera = ReadPose(in, "a keyframe");
  ReadMatrix(in, &k.information, "a keyframe");
  const std::uint8_t weak = in->U8("a keyframe");
  if (weak > 1) {
    Fail(name, "invalid content: keyframe " + std::to_string(k.id) + " has weak_since_previous " +
                   std::to_string(weak) + " (0 or 1)");
  }
  k.weak_since_previous = weak == 1;
  const std::uint32_t n = in->Count(8, "point ids");
  k.points.resize(n);
  for (PointId& id : k.points) id = in->I64("a point id");
  ReadMeasurements(in, k.id, &k.measurements, name);
  return k;
}

void ReadImages(ByteReader* in, std::uint32_t n, KeyFrameMapFile* file, const std::string& name) {
  for (std::uint32_t i = 0; i < n; ++i) {
    const int id = in->I32("an image pair");
    if (!file->images.empty() && id <= file->images.rbegin()->first) {
      Fail(name, "invalid content: images of keyframe " + std::to_string(id) + " out of order");
    }
    const std::string colour = in->Bytes(in->U32("a colour image"), "a colour image");
    const std::string depth = in->Bytes(in->U32("a depth image"), "a depth image");
    file->images.emplace(id, DecodeImages(colour, depth, file->camera, id, name));
  }
}

}  // namespace
}  // namespace map_file

KeyFrameMapFile ParseKeyFrameMap(const std::string& bytes, const std::string& name) {
  map_file::CheckHeader(bytes, name);
  map_file::ByteReader in(bytes, map_file::kChecksumFrom, name);
  KeyFrameMapFile file{map_file::ReadCamera(&in, name), 0, {}, {}};
  file.vocabulary_identity = GetLittleEndian(bytes, in.offset(), 8);
  in.Bytes(8, "the vocabulary identity");
  const std::uint32_t points = in.U32("the header");
  const std::uint32_t keyframes = in.U32("the header");
  const std::uint32_t images = in.U32("the header");
  in.CheckFits(points, map_file::kMinPointBytes, "map points");
  file.contents.points.reserve(points);
  for (std::uint32_t i = 0; i < points; ++i) {
    file.contents.points.push_back(map_file::ReadPoint(&in, name));
  }
  in.CheckFits(keyframes, map_file::kMinKeyFrameBytes, "keyframes");
  file.contents.keyframes.reserve(keyframes);
  for (std::uint32_t i = 0; i < keyframes; ++i) {
    file.contents.keyframes.push_back(map_file::ReadKeyFrame(&in, name));
  }
  in.CheckFits(images, map_file::kMinImagePairBytes, "image pairs");
  map_file::ReadImages(&in, images, &file, name);
  if (in.left() != 0) {
    throw KeyFrameMapError(name + ": invalid content: " + std::to_string(in.left()) +
                           " bytes after the last record");
  }
  const std::string problem = map_file::CheckContents(file);
  if (!problem.empty()) throw KeyFrameMapError(name + ": invalid content: " + problem);
  return file;
}

KeyFrameMapFile LoadKeyFrameMap(const std::string& path) {
  std::string bytes;
  try {
    bytes = ReadWholeFile(path, "LoadKeyFrameMap");
  } catch (const std::runtime_error& e) {
    throw KeyFrameMapError(e.what());
  }
  return ParseKeyFrameMap(bytes, path);
}

}  // namespace dslam
