// The rules of a keyframe map file's contents (CheckContents, shared by the writer and the
// reader) and CheckCompatible.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Cholesky>

#include "dslam/core/binary_io.h"
#include "dslam/core/config.h"
#include "keyframe_map_internal.h"

namespace dslam {
namespace map_file {
namespace {

constexpr char kMaxIndexWhy[] =
    "1073741823 (kKeyFrameMapMaxIndex: a run continuing the map would overflow an int)";

std::string Number(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.9g", v);
  return text;
}

// "" when T is finite and its rotation one (|R^T R - I| <= 1e-6, det R > 0), else why not.
std::string PoseProblem(const Eigen::Isometry3d& T) {
  if (!T.matrix().topRows<3>().allFinite()) return "a non-finite pose";
  const Eigen::Matrix3d R = T.linear();
  if (!((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() <= 1e-6) ||
      !(R.determinant() > 0.0)) {
    return "a pose whose rotation is not one";
  }
  return "";
}

// Whether `A` (finite) is symmetric (|A - A^T| <= 1e-6 |A|, Frobenius) and positive definite
// (a Cholesky factorisation of its symmetric part exists).
template <typename Matrix>
bool SymmetricPositiveDefinite(const Matrix& A) {
  if (!((A - A.transpose()).norm() <= 1e-6 * A.norm())) return false;
  const Matrix symmetric = 0.5 * (A + A.transpose());
  return Eigen::LLT<Matrix>(symmetric).info() == Eigen::Success;
}

std::string PointProblem(const MapPoint& p) {
  if (!p.p_world.allFinite() || !p.cov_world.allFinite() ||
      !std::isfinite(p.reference_distance_m)) {
    return "a non-finite position, covariance or reference distance";
  }
  if (!SymmetricPositiveDefinite(p.cov_world)) {
    return "a covariance (cov_world) that is not symmetric positive definite";
  }
  const cv::Mat& d = p.descriptor;
  if (!d.empty() && (d.rows != 1 || d.cols != kDescriptorBytes || d.type() != CV_8U)) {
    return "a descriptor that is neither empty nor 1x32 CV_8U";
  }
  return "";
}

std::string MeasurementProblem(const PointMeasurement& m) {
  if (!m.y_camera.allFinite() || !m.covariance.allFinite() || !std::isfinite(m.depth_mean_m) ||
      !std::isfinite(m.depth_sigma_m)) {
    return "is not finite";
  }
  if (!SymmetricPositiveDefinite(m.covariance)) {
    return "has a covariance that is not symmetric positive definite";
  }
  if (!(m.depth_sigma_m > 0.0)) return "has depth_sigma_m " + Number(m.depth_sigma_m) + ", not > 0";
  return "";
}

std::string KeyFrameProblem(const KeyFrame& k) {
  if (k.frame_index > kKeyFrameMapMaxIndex) {
    return "frame_index " + std::to_string(k.frame_index) + ", above " + kMaxIndexWhy;
  }
  if (!std::isfinite(k.stamp_s)) return "a non-finite stamp";
  if (!k.information.allFinite()) return "a non-finite information matrix";
  if (!k.information.isZero(0.0) && !SymmetricPositiveDefinite(k.information)) {
    return "an information matrix that is neither zero (unknown) nor symmetric positive definite";
  }
  std::string problem = PoseProblem(k.T_world_camera);
  if (problem.empty()) problem = PoseProblem(k.measurements.T_camera_world);
  if (!problem.empty()) return problem;
  for (const auto& entry : k.measurements.by_point) {
    problem = MeasurementProblem(entry.second);
    if (!problem.empty())
      return "a measurement of point " + std::to_string(entry.first) + " that " + problem;
  }
  return "";
}

// "" when `s` is in the ranges of KeyFrameMapSettings, else the first field out of range.
std::string SettingsProblem(const KeyFrameMapSettings& s) {
  const DepthNoiseConfig& n = s.depth_noise;
  if (s.orb_levels < 1) return "features.num_levels " + std::to_string(s.orb_levels) + ", not >= 1";
  if (!(std::isfinite(s.orb_scale_factor) && s.orb_scale_factor > 1.0)) {
    return "features.scale_factor " + Number(s.orb_scale_factor) + ", not finite and > 1";
  }
  if (!(std::isfinite(n.pixel_sigma_px) && n.pixel_sigma_px > 0.0)) {
    return "depth_noise.pixel_sigma_px " + Number(n.pixel_sigma_px) + ", not finite and > 0";
  }
  for (double v : {n.sigma_d_quadratic, n.sigma_d_constant_m, n.min_depth_m, n.max_depth_m}) {
    if (!(std::isfinite(v) && v >= 0.0)) {
      return "a depth_noise value " + Number(v) + ", not finite and >= 0";
    }
  }
  return "";
}

std::string ImagesProblem(const KeyFrameImages& images, const PinholeCamera& camera) {
  const cv::Size size(camera.width(), camera.height());
  const int colour = images.colour.type();
  if (images.colour.size() != size || (colour != CV_8UC3 && colour != CV_8UC1)) {
    return "a colour image that is not CV_8UC3 or CV_8UC1 of the camera's size";
  }
  if (images.depth_m.size() != size || images.depth_m.type() != CV_32FC1) {
    return "a depth image that is not CV_32FC1 of the camera's size";
  }
  return "";
}

// The first id of `ids` (by `id_of`) that is negative or not above the one before; -1: none.
template <typename List, typename IdOf>
long long FirstBadId(const List& list, IdOf id_of) {
  for (size_t i = 0; i < list.size(); ++i) {
    const long long id = id_of(list[i]);
    if (id < 0 || (i > 0 && id <= id_of(list[i - 1]))) return static_cast<long long>(i);
  }
  return -1;
}

std::string CameraText(const PinholeCamera& c) {
  const Distortion& d = c.distortion();
  char text[256];
  std::snprintf(text, sizeof(text),
                "%dx%d fx %.9g fy %.9g cx %.9g cy %.9g k1 %.9g k2 %.9g "
                "p1 %.9g p2 %.9g k3 %.9g",
                c.width(), c.height(), c.fx(), c.fy(), c.cx(), c.cy(), d.k1, d.k2, d.p1, d.p2,
                d.k3);
  return text;
}

bool Near(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(a)); }

}  // namespace

std::string CheckContents(const KeyFrameMapFile& file) {
  const auto& points = file.contents.points;
  const auto& keyframes = file.contents.keyframes;
  const long long bad_point = FirstBadId(points, [](const MapPoint& p) { return p.id; });
  if (bad_point >= 0) {
    return "map point id " + std::to_string(points[bad_point].id) +
           " is negative or not above the one before (ids ascending, each once)";
  }
  const long long bad_keyframe = FirstBadId(keyframes, [](const KeyFrame& k) { return k.id; });
  if (bad_keyframe >= 0) {
    return "keyframe id " + std::to_string(keyframes[bad_keyframe].id) +
           " is negative or not above the one before (ids ascending, each once)";
  }
  if (!points.empty() && points.back().id > kKeyFrameMapMaxPointId) {
    return "map point id " + std::to_string(points.back().id) + " is above " +
           std::to_string(kKeyFrameMapMaxPointId) +
           " (kKeyFrameMapMaxPointId: a run continuing the map would overflow a PointId)";
  }
  if (!keyframes.empty() && keyframes.back().id > kKeyFrameMapMaxIndex) {
    return "keyframe id " + std::to_string(keyframes.back().id) + " is above " + kMaxIndexWhy;
  }
  if (file.settings) {
    const std::string problem = SettingsProblem(*file.settings);
    if (!problem.empty()) return "settings: " + problem;
  }
  for (const MapPoint& p : points) {
    const std::string problem = PointProblem(p);
    if (!problem.empty()) return "map point " + std::to_string(p.id) + " has " + problem;
  }
  for (const KeyFrame& k : keyframes) {
    const std::string problem = KeyFrameProblem(k);
    if (!problem.empty()) return "keyframe " + std::to_string(k.id) + " has " + problem;
  }
  for (const auto& entry : file.images) {
    const auto at =
        std::lower_bound(keyframes.begin(), keyframes.end(), entry.first,
                         [](const KeyFrame& keyframe, int id) { return keyframe.id < id; });
    const bool known = at != keyframes.end() && at->id == entry.first;
    if (!known) return "images of keyframe " + std::to_string(entry.first) + ", not in the map";
    const std::string problem = ImagesProblem(entry.second, file.camera);
    if (!problem.empty()) return "keyframe " + std::to_string(entry.first) + " has " + problem;
  }
  return "";
}

}  // namespace map_file

namespace map_file {
namespace {

// "" when `a` (the file's) and `b` (the run's) are equal (numbers Near), else the first
// difference.
std::string SettingsDifference(const KeyFrameMapSettings& a, const KeyFrameMapSettings& b) {
  const auto differs = [](const char* key, double file, double run) {
    return "recorded with " + std::string(key) + " " + Number(file) + " but this run uses " +
           Number(run);
  };
  if (a.orb_levels != b.orb_levels) {
    return differs("features.num_levels", a.orb_levels, b.orb_levels);
  }
  if (!Near(a.orb_scale_factor, b.orb_scale_factor)) {
    return differs("features.scale_factor", a.orb_scale_factor, b.orb_scale_factor);
  }
  const DepthNoiseConfig& m = a.depth_noise;
  const DepthNoiseConfig& n = b.depth_noise;
  const std::pair<const char*, std::pair<double, double>> noise[] = {
      {"depth_noise.pixel_sigma_px", {m.pixel_sigma_px, n.pixel_sigma_px}},
      {"depth_noise.sigma_d_quadratic", {m.sigma_d_quadratic, n.sigma_d_quadratic}},
      {"depth_noise.sigma_d_constant_m", {m.sigma_d_constant_m, n.sigma_d_constant_m}},
      {"depth_noise.min_depth_m", {m.min_depth_m, n.min_depth_m}},
      {"depth_noise.max_depth_m", {m.max_depth_m, n.max_depth_m}}};
  for (const auto& [key, values] : noise) {
    if (!Near(values.first, values.second)) return differs(key, values.first, values.second);
  }
  return "";
}

}  // namespace
}  // namespace map_file

KeyFrameMapSettings KeyFrameMapSettingsOf(const Config& config) {
  return KeyFrameMapSettings{config.features.num_levels, config.features.scale_factor,
                             config.depth_noise};
}

std::string CheckCompatible(const KeyFrameMapFile& file, const PinholeCamera& camera,
                            std::uint64_t vocabulary_identity,
                            const KeyFrameMapSettings& settings) {
  const PinholeCamera& c = file.camera;
  const Distortion& d = c.distortion();
  const Distortion& e = camera.distortion();
  const bool same_camera =
      c.width() == camera.width() && c.height() == camera.height() &&
      map_file::Near(c.fx(), camera.fx()) && map_file::Near(c.fy(), camera.fy()) &&
      map_file::Near(c.cx(), camera.cx()) && map_file::Near(c.cy(), camera.cy()) &&
      map_file::Near(d.k1, e.k1) && map_file::Near(d.k2, e.k2) && map_file::Near(d.p1, e.p1) &&
      map_file::Near(d.p2, e.p2) && map_file::Near(d.k3, e.k3);
  if (!same_camera) {
    return "recorded with another camera (" + map_file::CameraText(c) + ") than this run's (" +
           map_file::CameraText(camera) + ")";
  }
  if (file.vocabulary_identity != vocabulary_identity) {
    return "recorded with vocabulary " + FormatIdentity(file.vocabulary_identity) +
           " but this run uses " + FormatIdentity(vocabulary_identity);
  }
  return file.settings ? map_file::SettingsDifference(*file.settings, settings) : "";
}

std::string KeyFrameMapWarning(const KeyFrameMapFile& file) {
  if (file.settings) return "";
  return "format version 1: the ORB and depth noise settings the map was made with are not in "
         "the file and cannot be checked against this run's";
}

}  // namespace dslam
