// The keyframe map file's writer: SerialiseKeyFrameMap and SaveKeyFrameMap (format in
// dslam/map_file/keyframe_map_file.h).
#include <algorithm>
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
  PutU32(kKeyFrameMapVersion, out);
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

}  // namespace map_file

std::string SerialiseKeyFrameMap(const KeyFrameMapFile& file) {
  const std::string problem = map_file::CheckContents(file);
  if (!problem.empty()) throw std::invalid_argument("SerialiseKeyFrameMap: " + problem);
  std::string out;
  map_file::PutHeader(file, &out);
  for (const MapPoint& point : file.contents.points) map_file::PutPoint(point, &out);
  for (const KeyFrame& keyframe : file.contents.keyframes) map_file::PutKeyFrame(keyframe, &out);
  for (const auto& entry : file.images) {
    map_file::PutI32(entry.first, &out);
    map_file::PutBytes(map_file::EncodeColour(entry.second.colour), &out);
    map_file::PutBytes(map_file::EncodeDepth(entry.second.depth_m), &out);
  }
  std::string size;
  PutU64(out.size(), &size);
  out.replace(12, 8, size);
  std::string checksum;
  PutU64(Fnv1a64(out.data() + map_file::kChecksumFrom, out.size() - map_file::kChecksumFrom),
         &checksum);
  out.replace(20, 8, checksum);
  return out;
}

void SaveKeyFrameMap(const std::string& path, const KeyFrameMapFile& file) {
  WriteFileAtomically(path, SerialiseKeyFrameMap(file), "SaveKeyFrameMap");
}

}  // namespace dslam
