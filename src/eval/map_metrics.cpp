// The static map against synthetic truth (map_metrics.h).
#include "dslam/eval/map_metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>

#include "dslam/core/depth_conversion.h"
#include "dslam/core/image_limits.h"
#include "dslam/io/dataset_io.h"
#include "dslam/io/trajectory_io.h"

namespace dslam {
namespace {

constexpr double kStampTolerance_s = 1e-4;

const MapMetricsOptions& CheckOptions(const MapMetricsOptions& options) {
  if (options.pixel_stride < 1 || options.frame_stride < 1) {
    throw std::invalid_argument("map metrics: pixel_stride and frame_stride must be >= 1");
  }
  return options;
}

/// Index of the entry of `stamps` (sorted) within kStampTolerance_s of `t`, or -1.
template <typename T, typename StampOf>
int FindStamp(const std::vector<T>& items, double t, StampOf stamp_of) {
  const auto it = std::lower_bound(items.begin(), items.end(), t - kStampTolerance_s,
                                   [&](const T& item, double s) { return stamp_of(item) < s; });
  if (it == items.end() || std::abs(stamp_of(*it) - t) > kStampTolerance_s) return -1;
  return static_cast<int>(it - items.begin());
}

cv::Mat ReadMask(const std::string& path) {
  CheckImageFile(path, false);
  const cv::Mat mask = cv::imread(path, cv::IMREAD_ANYDEPTH);
  if (mask.empty() || mask.type() != CV_16UC1) {
    throw std::runtime_error("cannot read 16-bit mask " + path);
  }
  return mask;
}

}  // namespace

MapReferenceBuilder::MapReferenceBuilder(const MapMetricsOptions& options)
    : options_(CheckOptions(options)), static_(options.voxel_m), dynamic_(options.voxel_m) {}

void MapReferenceBuilder::AddFrame(const cv::Mat& depth_true_m, const cv::Mat& mask,
                                   const PinholeCamera& camera,
                                   const Eigen::Isometry3d& T_world_camera) {
  if (depth_true_m.type() != CV_32FC1 || mask.type() != CV_16UC1 ||
      depth_true_m.size() != mask.size()) {
    throw std::invalid_argument("map reference: depth must be CV_32FC1, mask CV_16UC1, same size");
  }
  const int step = options_.pixel_stride;
  for (int v = 0; v < depth_true_m.rows; v += step) {
    for (int u = 0; u < depth_true_m.cols; u += step) {
      const double d = depth_true_m.at<float>(v, u);
      if (!(d >= options_.min_depth_m && d <= options_.max_depth_m)) continue;
      const Eigen::Vector2d uv = camera.Undistort(Eigen::Vector2d(u, v));
      const Eigen::Vector3d p_world = T_world_camera * camera.BackProject(uv, d);
      (mask.at<uint16_t>(v, u) == 0 ? static_ : dynamic_).Add(p_world);
    }
  }
  ++frames_;
}

MapReference MapReferenceBuilder::Build() const {
  MapReference reference;
  reference.static_points = static_.Centroids();
  reference.dynamic_points = dynamic_.Centroids();
  reference.frames = frames_;
  return reference;
}

MapReference LoadMapReference(const std::string& folder, const MapMetricsOptions& options) {
  const CameraYaml yaml = LoadCameraYaml(folder + "/camera.yaml");
  const std::vector<StampedFile> depths = ReadFileList(folder + "/depth_true.txt");
  std::vector<StampedFile> masks = ReadFileList(folder + "/mask.txt");
  std::sort(masks.begin(), masks.end(),
            [](const StampedFile& a, const StampedFile& b) { return a.stamp_s < b.stamp_s; });
  const Trajectory poses = ReadTumTrajectory(folder + "/groundtruth.txt");  // sorted
  if (depths.empty()) throw std::runtime_error(folder + "/depth_true.txt lists no images");
  MapReferenceBuilder builder(options);
  for (size_t i = 0; i < depths.size(); i += options.frame_stride) {
    const double t = depths[i].stamp_s;
    const int mask = FindStamp(masks, t, [](const StampedFile& f) { return f.stamp_s; });
    const int pose = FindStamp(poses, t, [](const StampedPose& p) { return p.stamp_s; });
    if (mask < 0 || pose < 0) {
      throw std::runtime_error(folder + ": no mask or ground-truth pose at depth_true stamp " +
                               std::to_string(t));
    }
    builder.AddFrame(ReadDepthPng(folder + "/" + depths[i].path, yaml.depth_scale),
                     ReadMask(folder + "/" + masks[mask].path), *yaml.camera,
                     poses[pose].T_world_camera);
  }
  return builder.Build();
}

MapMetrics EvaluateMap(const std::vector<Eigen::Vector3d>& map_world_m,
                       const MapReference& reference, double radius_m) {
  std::vector<Eigen::Vector3d> map;
  map.reserve(map_world_m.size());
  for (const Eigen::Vector3d& p : map_world_m) {
    if (p.allFinite()) map.push_back(p);
  }
  const RadiusIndex static_index(reference.static_points, radius_m);
  const RadiusIndex dynamic_index(reference.dynamic_points, radius_m);
  const RadiusIndex map_index(map, radius_m);
  MapMetrics m;
  m.map_points = map.size();
  m.static_reference_points = reference.static_points.size();
  m.dynamic_reference_points = reference.dynamic_points.size();
  for (const Eigen::Vector3d& p : map) {
    const bool near_static = static_index.AnyWithin(p);
    m.near_static_points += near_static ? 1 : 0;
    if (!near_static && dynamic_index.AnyWithin(p)) ++m.ghost_points;
  }
  for (const Eigen::Vector3d& q : reference.static_points) {
    if (map_index.AnyWithin(q)) ++m.covered_static_points;
  }
  const auto share = [](size_t count, size_t of) {
    return of > 0 ? static_cast<double>(count) / static_cast<double>(of) : 0.0;
  };
  m.ghost_share = share(m.ghost_points, m.map_points);
  m.static_share = share(m.near_static_points, m.map_points);
  m.static_coverage = share(m.covered_static_points, m.static_reference_points);
  return m;
}

}  // namespace dslam
