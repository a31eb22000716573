#include "dslam/mapping/point_carrier.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "cell_grid.h"
#include "dslam/tracking/id_set.h"

namespace dslam {
namespace {

/// The flow runs on images of half the resolution: pixel (u, v) there is (2u, 2v) here
/// (cv::pyrDown's sampling).
constexpr float kFlowScale = 0.5f;

bool HasRegionPoints(const DynamicMask& mask) {
  return std::any_of(mask.regions.begin(), mask.regions.end(),
                     [](const DynamicRegion& region) { return !region.points.empty(); });
}

/// Per cell of `mask`: 1 where a region point already lies.
std::vector<uint8_t> OccupiedCells(const DynamicMask& mask) {
  std::vector<uint8_t> occupied(mask.labels.total(), 0);
  for (const DynamicRegion& region : mask.regions) {
    for (int cell : region.point_cells) {
      if (cell >= 0) occupied[cell] = 1;
    }
  }
  return occupied;
}

}  // namespace

PointCarrier::PointCarrier(const ObjectsConfig& config, const DynamicMaskConfig& mask_config)
    : window_(kWindowPx, kWindowPx),
      levels_(kLevels),
      max_error_px_(kMaxErrorPx),
      max_speed_mps_(config.max_point_speed_mps),
      max_points_(kMaxPoints),
      max_depth_m_(mask_config.max_depth_m) {}

void PointCarrier::Reset() {
  previous_pyramid_.clear();
  previous_ids_.clear();
  previous_uv_raw_.clear();
  previous_world_.clear();
}

std::vector<cv::Mat> PointCarrier::Pyramid(const RgbdFrame& frame) {
  cv::Mat half;
  cv::pyrDown(frame.Grey(), half);
  std::vector<cv::Mat> pyramid;
  pyramid.swap(spare_pyramid_);  // same sizes as this frame's: no allocation
  cv::buildOpticalFlowPyramid(half, pyramid, window_, levels_ - 1);
  return pyramid;
}

CarriedFlow PointCarrier::Track(const RgbdFrame& frame, const std::vector<ObservedPoint>& points) {
  CarriedFlow flow;
  if (previous_ids_.empty()) return flow;
  flow.pyramid = Pyramid(frame);
  if (previous_pyramid_.empty() || previous_pyramid_[0].size() != flow.pyramid[0].size()) {
    return flow;  // the image size changed: nothing to follow
  }
  IdSet matched(points.size());
  for (const ObservedPoint& point : points) matched.Insert(point.id);
  std::vector<size_t> lost;  // the previous points the front end did not find
  for (size_t i = 0; i < previous_ids_.size(); ++i) {
    if (!matched.Contains(previous_ids_[i])) lost.push_back(i);
  }
  const size_t take = std::min(lost.size(), static_cast<size_t>(max_points_));
  if (take == 0) return flow;
  std::vector<size_t> chosen(take);
  std::vector<cv::Point2f> from(take), to, back;
  for (size_t k = 0; k < take; ++k) {
    chosen[k] = lost[k * lost.size() / take];  // evenly spread
    from[k] = previous_uv_raw_[chosen[k]] * kFlowScale;
  }
  std::vector<uint8_t> status, back_status;
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(previous_pyramid_, flow.pyramid, from, to, status, error, window_,
                           levels_ - 1);
  cv::calcOpticalFlowPyrLK(flow.pyramid, previous_pyramid_, to, back, back_status, error, window_,
                           levels_ - 1);
  for (size_t k = 0; k < take; ++k) {
    if (!status[k] || !back_status[k]) continue;
    if (cv::norm(back[k] - from[k]) / kFlowScale > max_error_px_) continue;
    flow.ids.push_back(previous_ids_[chosen[k]]);
    flow.uv_raw.push_back(to[k] / kFlowScale);
    flow.from_world.push_back(previous_world_[chosen[k]]);
  }
  return flow;
}

int PointCarrier::Attach(CarriedFlow flow, const RgbdFrame& frame,
                         const Eigen::Isometry3d& T_world_camera,
                         const std::vector<ObservedPoint>& points, DynamicMask* mask) {
  if (flow.pyramid.empty()) {
    if (!HasRegionPoints(*mask)) {
      Reset();  // nothing carried now or into the next frame: no pyramid needed
      return 0;
    }
    flow.pyramid = Pyramid(frame);
  }
  std::vector<std::pair<PointId, cv::Point2f>> carried;
  std::vector<uint8_t> occupied = OccupiedCells(*mask);
  const double max_step_m = max_speed_mps_ * (frame.stamp_s - previous_stamp_s_);
  const auto* labels = mask->labels.ptr<uint16_t>();
  for (size_t i = 0; i < flow.ids.size(); ++i) {
    const int u = static_cast<int>(std::lround(flow.uv_raw[i].x));
    const int v = static_cast<int>(std::lround(flow.uv_raw[i].y));
    const int cell = mask->CellAt(u, v);
    if (cell < 0 || labels[cell] == 0) continue;  // off the moving things (or outside the image)
    const uint16_t label = labels[cell];
    if (occupied[cell]) continue;
    const double z = ValidPixelDepth(frame.depth_m, u, v, max_depth_m_);
    if (z <= 0.0) continue;
    const Eigen::Vector3d p_world =
        T_world_camera *
        BackProjectRawPixel(*frame.camera, Eigen::Vector2d(flow.uv_raw[i].x, flow.uv_raw[i].y), z);
    if ((p_world - flow.from_world[i]).norm() > max_step_m) continue;  // another surface
    DynamicRegion& region = mask->regions[label - 1];
    region.points.push_back(flow.ids[i]);
    region.points_world.push_back(p_world);
    region.point_cells.push_back(cell);
    occupied[cell] = 1;
    carried.emplace_back(flow.ids[i], flow.uv_raw[i]);
  }
  Remember(*mask, points, carried, std::move(flow.pyramid), frame.stamp_s);
  return static_cast<int>(carried.size());
}

void PointCarrier::Remember(const DynamicMask& mask, const std::vector<ObservedPoint>& points,
                            const std::vector<std::pair<PointId, cv::Point2f>>& carried,
                            std::vector<cv::Mat> pyramid, double stamp_s) {
  std::unordered_map<PointId, cv::Point2f> uv_of;
  for (const ObservedPoint& point : points) {
    uv_of[point.id] =
        cv::Point2f(static_cast<float>(point.uv_raw.x()), static_cast<float>(point.uv_raw.y()));
  }
  for (const auto& [id, uv] : carried) uv_of[id] = uv;
  previous_ids_.clear();
  previous_uv_raw_.clear();
  previous_world_.clear();
  for (const DynamicRegion& region : mask.regions) {
    for (size_t i = 0; i < region.points.size(); ++i) {
      const auto uv = uv_of.find(region.points[i]);
      if (uv == uv_of.end()) continue;
      previous_ids_.push_back(region.points[i]);
      previous_uv_raw_.push_back(uv->second);
      previous_world_.push_back(region.points_world[i]);
    }
  }
  previous_stamp_s_ = stamp_s;
  if (previous_ids_.empty()) pyramid.clear();
  spare_pyramid_.swap(previous_pyramid_);
  previous_pyramid_ = std::move(pyramid);
}

}  // namespace dslam
