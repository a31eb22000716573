// The keyframe map file's writer: SerialiseKeyFrameMap and SaveKeyFrameMap (format in
// dslam/map_file/keyframe_map_file.h), streamed record by record, the checksum computed as the
// bytes pass and written with the size into the header at the end.
#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "dslam/core/binary_io.h"
#include "keyframe_map_internal.h"

namespace dslam {
namespace map_file {
namespace {

void PutI32(int v, std::string* out) { PutU32(static_cast<std::uint32_t>(v), out); }
void PutI64(std::int64_t v, std::string* out) { PutU64(static_cast<std::uint64_t>(v), out); }

template <typename Matrix>
void PutMatrix(const Matrix& m, std::string* out) {
  for (int r = 0; r < m.rows(); ++r) {
    for (int c = 0; c < m.cols(); ++c) PutF64(m(r, c), out);
  }
}

void PutHeader(const KeyFrameMapFile& file, std::string* out) {
  out->append(kMagic, sizeof(kMagic));
  PutU32(file.settings ? kKeyFrameMapVersion : 1, out);
  PutU64(0, out);  // file size and checksum: filled in when the body is complete
  PutU64(0, out);
  const PinholeCamera& camera = file.camera;
  PutU32(static_cast<std::uint32_t>(camera.width()), out);
  PutU32(static_cast<std::uint32_t>(camera.height()), out);
  const Distortion& d = camera.distortion();
  for (double v :
       {camera.fx(), camera.fy(), camera.cx(), camera.cy(), d.k1, d.k2, d.p1, d.p2, d.k3}) {
    PutF64(v, out);
  }
  PutU64(file.vocabulary_identity, out);
  PutU32(static_cast<std::uint32_t>(file.contents.points.size()), out);
  PutU32(static_cast<std::uint32_t>(file.contents.keyframes.size()), out);
  PutU32(static_cast<std::uint32_t>(file.images.size()), out);
  if (!file.settings) return;  // version 1
  const KeyFrameMapSettings& settings = *file.settings;
  PutI32(settings.orb_levels, out);
  const DepthNoiseConfig& noise = settings.depth_noise;
  for (double v : {settings.orb_scale_factor, noise.pixel_sigma_px, noise.sigma_d_quadratic,
                   noise.sigma_d_constant_m, noise.min_depth_m, noise.max_depth_m}) {
    PutF64(v, out);
  }
}

void PutPoint(const MapPoint& p, std::string* out) {
  PutI64(p.id, out);
  PutMatrix(p.p_world, out);
  PutMatrix(p.cov_world, out);
  const int length = p.descriptor.empty() ? 0 : kDescriptorBytes;
  out->push_back(static_cast<char>(length));
  if (length > 0) out->append(reinterpret_cast<const char*>(p.descriptor.ptr<uchar>(0)), length);
  PutI32(p.octave, out);
  PutI32(p.created_feature, out);
  PutF64(p.reference_distance_m, out);
  out->push_back(static_cast<char>((p.marked ? 1 : 0) | (p.candidate ? 2 : 0)));
  for (int v : {p.created_frame, p.last_seen_frame, p.times_visible, p.times_found,
                p.isolated_frames, p.static_streak, p.dynamic_frames}) {
    PutI32(v, out);
  }
}

void PutMeasurements(const FrameMeasurements& measurements, std::string* out) {
  PutPose(measurements.T_camera_world, out);
  std::vector<PointId> ids;
  ids.reserve(measurements.by_point.size());
  for (const auto& entry : measurements.by_point) ids.push_back(entry.first);
  std::sort(ids.begin(), ids.end());
  PutU32(static_cast<std::uint32_t>(ids.size()), out);
  for (PointId id : ids) {
    const PointMeasurement& m = measurements.by_point.at(id);
    PutI64(id, out);
    PutMatrix(m.y_camera, out);
    PutMatrix(m.covariance, out);
    PutF64(m.depth_mean_m, out);
    PutF64(m.depth_sigma_m, out);
  }
}

void PutKeyFrame(const KeyFrame& k, std::string* out) {
  PutI32(k.id, out);
  PutI32(k.frame_index, out);
  PutF64(k.stamp_s, out);
  PutPose(k.T_world_camera, out);
  PutMatrix(k.information, out);
  out->push_back(static_cast<char>(k.weak_since_previous ? 1 : 0));
  PutU32(static_cast<std::uint32_t>(k.points.size()), out);
  for (PointId id : k.points) PutI64(id, out);
  PutMeasurements(k.measurements, out);
}

void PutBytes(const std::string& bytes, std::string* out) {
  PutU32(static_cast<std::uint32_t>(bytes.size()), out);
  out->append(bytes);
}

}  // namespace

void PutPose(const Eigen::Isometry3d& T, std::string* out) {
  PutMatrix(T.matrix().topRows<3>(), out);
}

void WriteKeyFrameMap(const KeyFrameMapFile& file, std::ostream* out) {
  constexpr std::size_t kBatchBytes = 1 << 16;  // records gathered per write
  HashingWriter writer(out);
  std::string record;
  PutHeader(file, &record);
  for (const MapPoint& point : file.contents.points) {
    PutPoint(point, &record);
    if (record.size() >= kBatchBytes) writer.Write(&record);
  }
  for (const KeyFrame& keyframe : file.contents.keyframes) {
    PutKeyFrame(keyframe, &record);
    if (record.size() >= kBatchBytes) writer.Write(&record);
  }
  for (const auto& entry : file.images) {
    if (!writer.ok()) return;  // the stream failed (e.g. a full disk): the caller sees it
    PutI32(entry.first, &record);
    PutBytes(EncodeColour(entry.second.colour), &record);
    PutBytes(EncodeDepth(entry.second.depth_m), &record);
    writer.Write(&record);
  }
  writer.Write(&record);
  PutU64(writer.size(), &record);
  PutU64(writer.checksum(), &record);
  out->seekp(12);
  out->write(record.data(), static_cast<std::streamsize>(record.size()));
  out->seekp(0, std::ios::end);
}

}  // namespace map_file

std::string SerialiseKeyFrameMap(const KeyFrameMapFile& file) {
  const std::string problem = map_file::CheckContents(file);
  if (!problem.empty()) throw std::invalid_argument("SerialiseKeyFrameMap: " + problem);
  std::ostringstream out(std::ios::binary);
  map_file::WriteKeyFrameMap(file, &out);
  return std::move(out).str();
}

void SaveKeyFrameMap(const std::string& path, const KeyFrameMapFile& file, PreviousFile previous) {
  const std::string problem = map_file::CheckContents(file);
  if (!problem.empty()) throw std::invalid_argument("SaveKeyFrameMap: " + problem);
  WriteFileAtomically(
      path, [&](std::ostream& out) { map_file::WriteKeyFrameMap(file, &out); }, "SaveKeyFrameMap",
      previous);
}

}  // namespace dslam
