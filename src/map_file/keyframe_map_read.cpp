// The keyframe map file's reader: ParseKeyFrameMap and LoadKeyFrameMap (format in
// dslam/map_file/keyframe_map_file.h). The header is checked first (magic, version, size,
// checksum: a file is streamed once for it), then the body is read as a stream with every count
// bounded by the bytes left, then the contents are checked against the rules the writer keeps
// (CheckContents).
#include <algorithm>
#include <cstring>
#include <fstream>
#include <istream>
#include <optional>
#include <vector>

#include "dslam/core/binary_io.h"
#include "keyframe_map_internal.h"

namespace dslam {
namespace map_file {
namespace {

[[noreturn]] void Fail(const std::string& name, const std::string& why) {
  throw KeyFrameMapError(name + ": " + why);
}

std::uint64_t HeaderField(const std::string& head, std::size_t offset, int size) {
  return GetLittleEndian(head, offset, size);
}

}  // namespace

std::uint32_t CheckHeader(const std::string& head, std::uint64_t size, const std::string& name) {
  if (size == 0) Fail(name, "empty file, not a dslam keyframe map");
  const std::size_t compared = std::min(head.size(), sizeof(kMagic));
  if (std::memcmp(head.data(), kMagic, compared) != 0) {
    Fail(name, "not a dslam keyframe map (its first bytes are not the magic \"DSLAMKFM\")");
  }
  const std::string got = ", got " + std::to_string(size);
  if (size < 12) Fail(name, "truncated: expected at least 12 bytes" + got);
  const std::uint64_t version = HeaderField(head, 8, 4);
  if (version != 1 && version != kKeyFrameMapVersion) {
    Fail(name, "unsupported format version " + std::to_string(version) +
                   " (this build reads 1 and " + std::to_string(kKeyFrameMapVersion) + ")");
  }
  const std::size_t header = version == 1 ? kKeyFrameMapV1HeaderBytes : kKeyFrameMapHeaderBytes;
  if (size < header) {
    Fail(name,
         "truncated: expected at least " + std::to_string(header) + " bytes (the header)" + got);
  }
  const std::uint64_t expected = HeaderField(head, 12, 8);
  if (size < expected)
    Fail(name, "truncated: expected " + std::to_string(expected) + " bytes" + got);
  if (size > expected) {
    Fail(name, "corrupt: " + std::to_string(size) + " bytes, the header gives " +
                   std::to_string(expected));
  }
  return static_cast<std::uint32_t>(version);
}

void CheckChecksum(const std::string& head, std::uint64_t checksum, const std::string& name) {
  if (HeaderField(head, 20, 8) != checksum) Fail(name, "checksum mismatch: the file is corrupt");
}

namespace {

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

KeyFrameMapSettings ReadSettings(ByteReader* in) {
  KeyFrameMapSettings settings;
  settings.orb_levels = in->I32("the settings");
  double v[6];
  in->F64s(v, 6, "the settings");
  settings.orb_scale_factor = v[0];
  settings.depth_noise = DepthNoiseConfig{v[1], v[2], v[3], v[4], v[5]};
  return settings;
}

// The header's fields from the camera on (the reader at kChecksumFrom); the counts of points,
// keyframes and image pairs into `counts`.
KeyFrameMapFile ReadHeaderFields(ByteReader* in, std::uint32_t version, std::uint32_t counts[3],
                                 const std::string& name) {
  KeyFrameMapFile file{ReadCamera(in, name), 0, {}, {}, std::nullopt};
  file.vocabulary_identity = in->U64("the vocabulary identity");
  for (int i = 0; i < 3; ++i) counts[i] = in->U32("the header");
  if (version >= 2) file.settings = ReadSettings(in);
  return file;
}

}  // namespace

KeyFrameMapFile ReadKeyFrameMap(std::istream* stream, std::uint64_t size, std::uint32_t version,
                                const std::string& name) {
  ByteReader in(stream, kChecksumFrom, size, name);
  std::uint32_t counts[3];
  KeyFrameMapFile file = ReadHeaderFields(&in, version, counts, name);
  in.CheckFits(counts[0], kMinPointBytes, "map points");
  file.contents.points.reserve(counts[0]);
  for (std::uint32_t i = 0; i < counts[0]; ++i)
    file.contents.points.push_back(ReadPoint(&in, name));
  in.CheckFits(counts[1], kMinKeyFrameBytes, "keyframes");
  file.contents.keyframes.reserve(counts[1]);
  for (std::uint32_t i = 0; i < counts[1]; ++i) {
    file.contents.keyframes.push_back(ReadKeyFrame(&in, name));
  }
  in.CheckFits(counts[2], kMinImagePairBytes, "image pairs");
  ReadImages(&in, counts[2], &file, name);
  if (in.left() != 0) {
    Fail(name, "invalid content: " + std::to_string(in.left()) + " bytes after the last record");
  }
  const std::string problem = CheckContents(file);
  if (!problem.empty()) Fail(name, "invalid content: " + problem);
  return file;
}

namespace {

// The FNV-1a hash of `in`'s bytes from kChecksumFrom to `size`, read in pieces.
std::uint64_t StreamChecksum(std::istream* in, std::uint64_t size, const std::string& name) {
  std::vector<char> buffer(1 << 16);
  std::uint64_t hash = kFnv1a64Basis;
  in->seekg(static_cast<std::streamoff>(kChecksumFrom));
  for (std::uint64_t left = size - kChecksumFrom; left > 0;) {
    const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(left, buffer.size()));
    in->read(buffer.data(), static_cast<std::streamsize>(n));
    if (static_cast<std::size_t>(in->gcount()) != n) {
      Fail(name, "read error (the file ended early or changed while it was read)");
    }
    hash = Fnv1a64Update(hash, buffer.data(), n);
    left -= n;
  }
  return hash;
}

}  // namespace
}  // namespace map_file

KeyFrameMapFile ParseKeyFrameMap(const std::string& bytes, const std::string& name) {
  const std::uint32_t version = map_file::CheckHeader(bytes, bytes.size(), name);
  map_file::CheckChecksum(
      bytes,
      Fnv1a64(bytes.data() + map_file::kChecksumFrom, bytes.size() - map_file::kChecksumFrom),
      name);
  map_file::StringViewBuf buffer(bytes);
  std::istream in(&buffer);
  in.ignore(static_cast<std::streamsize>(map_file::kChecksumFrom));
  return map_file::ReadKeyFrameMap(&in, bytes.size(), version, name);
}

KeyFrameMapFile LoadKeyFrameMap(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) map_file::Fail(path, "cannot open the file");
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  if (end < 0) map_file::Fail(path, "cannot read the file");
  const auto size = static_cast<std::uint64_t>(end);
  in.seekg(0);
  std::string head(static_cast<std::size_t>(std::min<std::uint64_t>(size, kKeyFrameMapHeaderBytes)),
                   '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  if (static_cast<std::size_t>(in.gcount()) != head.size()) map_file::Fail(path, "read error");
  const std::uint32_t version = map_file::CheckHeader(head, size, path);
  map_file::CheckChecksum(head, map_file::StreamChecksum(&in, size, path), path);
  in.clear();
  in.seekg(static_cast<std::streamoff>(map_file::kChecksumFrom));
  return map_file::ReadKeyFrameMap(&in, size, version, path);
}

}  // namespace dslam
