#include "dslam/synth/sequence.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "dslam/core/depth_conversion.h"
#include "dslam/synth/motion_blur.h"
#include "dslam/synth/render.h"

namespace dslam {
namespace synth {
namespace {

constexpr int kPathSegments = 4;     ///< poses along the exposure for MaxImagePathPx
constexpr int kPathPixelStride = 8;  ///< [px] grid spacing for MaxImagePathPx

/// For each pixel of the distorted `camera`, where its ray meets the image of `ideal` [px]
/// (cv::undistortPoints with camera's K and distortion, projected with ideal's K).
void IdealPixelMaps(const PinholeCamera& camera, const PinholeCamera& ideal, cv::Mat* map_u,
                    cv::Mat* map_v) {
  std::vector<cv::Point2f> distorted;
  for (int v = 0; v < camera.height(); ++v) {
    for (int u = 0; u < camera.width(); ++u) distorted.emplace_back(u, v);
  }
  const cv::Matx33d K(camera.fx(), 0, camera.cx(), 0, camera.fy(), camera.cy(), 0, 0, 1);
  const cv::Matx33d K_ideal(ideal.fx(), 0, ideal.cx(), 0, ideal.fy(), ideal.cy(), 0, 0, 1);
  const Distortion& d = camera.distortion();
  const std::vector<double> coefficients = {d.k1, d.k2, d.p1, d.p2, d.k3};
  std::vector<cv::Point2f> undistorted;
  cv::undistortPoints(distorted, undistorted, K, coefficients, cv::noArray(), K_ideal,
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-9));
  *map_u = cv::Mat(camera.height(), camera.width(), CV_32FC1);
  *map_v = cv::Mat(camera.height(), camera.width(), CV_32FC1);
  for (size_t i = 0; i < undistorted.size(); ++i) {
    map_u->at<float>(static_cast<int>(i)) = undistorted[i].x;
    map_v->at<float>(static_cast<int>(i)) = undistorted[i].y;
  }
}

/// [px] margin around the ideal image: covers where the distorted image's border pixels look.
int MarginPx(const cv::Mat& map_u, const cv::Mat& map_v, int width, int height) {
  double u_min, u_max, v_min, v_max;
  cv::minMaxLoc(map_u, &u_min, &u_max);
  cv::minMaxLoc(map_v, &v_min, &v_max);
  const double beyond = std::max({-u_min, u_max - (width - 1), -v_min, v_max - (height - 1), 0.0});
  return static_cast<int>(std::ceil(beyond)) + 2;
}

/// Replaces out->colour_clean (the sharp render at the frame's time) by the mean of the sub-frame
/// renders over the exposure (motion_blur.h); the middle sub-frame is the sharp render itself.
void BlurColour(const SyntheticSequence& sequence, int index, SyntheticFrame* out) {
  const Scenario& sc = sequence.scenario();
  const ExposureParams& exposure = sc.camera.exposure;
  const double t = index / sc.fps;
  out->blur_path_px = MaxImagePathPx(
      *sequence.render_camera(), out->depth_true_m, out->T_world_camera,
      ExposurePath(sc.camera, t, sc.seed, exposure.exposure_s, kPathSegments), kPathPixelStride);
  out->colour_subframes = SubframeCount(out->blur_path_px, exposure);
  if (out->colour_subframes == 1) return;
  std::vector<cv::Mat> colours;
  for (double offset : SubframeOffsets(exposure.exposure_s, out->colour_subframes)) {
    if (offset == 0.0) {
      colours.push_back(out->colour_clean);
      continue;
    }
    colours.push_back(RenderScene(sequence.GeometryAtTime(t + offset), *sequence.render_camera(),
                                  CameraPoseAt(sc.camera, t + offset, sc.seed))
                          .colour);
  }
  out->colour_clean = MeanColour(colours);
}

}  // namespace

SyntheticSequence::SyntheticSequence(Scenario scenario) : scenario_(std::move(scenario)) {
  const SensorParams& s = scenario_.sensor;
  camera_ =
      std::make_shared<PinholeCamera>(s.width, s.height, s.fx, s.fy, s.cx, s.cy, s.distortion);
  render_camera_ = camera_;
  if (!s.distortion.IsZero()) {
    const PinholeCamera same_centre(s.width, s.height, s.fx, s.fy, s.cx, s.cy);
    cv::Mat map_u, map_v;
    IdealPixelMaps(*camera_, same_centre, &map_u, &map_v);
    const int m = MarginPx(map_u, map_v, s.width, s.height);
    render_camera_ = std::make_shared<PinholeCamera>(s.width + 2 * m, s.height + 2 * m, s.fx, s.fy,
                                                     s.cx + m, s.cy + m);
    map_u_ = map_u + static_cast<float>(m);
    map_v_ = map_v + static_cast<float>(m);
  }
  static_scene_ = BuildStaticScene(scenario_.room, scenario_.seed);
}

void SyntheticSequence::Distort(SyntheticFrame* frame) const {
  if (render_camera_ == camera_) return;
  const auto warp = [&](const cv::Mat& image, int interpolation) {
    cv::Mat out;
    cv::remap(image, out, map_u_, map_v_, interpolation, cv::BORDER_CONSTANT, cv::Scalar::all(0));
    return out;
  };
  frame->colour_clean = warp(frame->colour_clean, cv::INTER_LINEAR);
  frame->depth_true_m = warp(frame->depth_true_m, cv::INTER_NEAREST);
  frame->mask = warp(frame->mask, cv::INTER_NEAREST);
}

double SyntheticSequence::StampOf(int index) const {
  const double stamp = scenario_.start_stamp_s + index / scenario_.fps;
  return std::round(stamp * 1e6) / 1e6;
}

Eigen::Isometry3d SyntheticSequence::PoseOf(int index) const {
  return CameraPoseAt(scenario_.camera, index / scenario_.fps, scenario_.seed);
}

SceneGeometry SyntheticSequence::GeometryAt(int index) const {
  return GeometryAtTime(index / scenario_.fps);
}

SceneGeometry SyntheticSequence::GeometryAtTime(double t) const {
  SceneGeometry scene = static_scene_;
  uint16_t id = 1;
  for (const WalkerParams& walker : scenario_.walkers) AppendWalker(walker, t, id++, &scene);
  for (const MovingBoxParams& box : scenario_.boxes) AppendMovingBox(box, t, id++, &scene);
  for (const SheetParams& sheet : scenario_.sheets) AppendSheet(sheet, t, id++, &scene);
  return scene;
}

SyntheticFrame SyntheticSequence::RenderFrame(int index) const {
  SyntheticFrame out;
  out.index = index;
  out.T_world_camera = PoseOf(index);
  const RenderedImages images = RenderScene(GeometryAt(index), *render_camera_, out.T_world_camera);
  out.colour_clean = images.colour;
  out.depth_true_m = images.depth_m;
  out.mask = images.mask;
  if (scenario_.camera.exposure.exposure_s > 0.0) BlurColour(*this, index, &out);
  Distort(&out);
  out.dynamic_fraction =
      static_cast<double>(cv::countNonZero(out.mask)) / static_cast<double>(out.mask.total());
  out.frame.stamp_s = StampOf(index);
  out.frame.camera = camera_;
  ApplySensorModel(scenario_.sensor, scenario_.seed, index, out.colour_clean, out.depth_true_m,
                   &out.frame.colour, &out.depth_units);
  out.frame.depth_m = DepthFromScaledUint16(out.depth_units, scenario_.sensor.depth_scale);
  return out;
}

}  // namespace synth
}  // namespace dslam
