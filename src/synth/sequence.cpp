#include "dslam/synth/sequence.h"

#include <cmath>
#include <utility>
#include <vector>

#include "dslam/core/depth_conversion.h"
#include "dslam/synth/motion_blur.h"
#include "dslam/synth/render.h"

namespace dslam {
namespace synth {
namespace {

constexpr int kPathSegments = 4;     ///< poses along the exposure for MaxImagePathPx
constexpr int kPathPixelStride = 8;  ///< [px] grid spacing for MaxImagePathPx

/// Replaces out->colour_clean (the sharp render at the frame's time) by the mean of the sub-frame
/// renders over the exposure (motion_blur.h); the middle sub-frame is the sharp render itself.
void BlurColour(const SyntheticSequence& sequence, int index, SyntheticFrame* out) {
  const Scenario& sc = sequence.scenario();
  const ExposureParams& exposure = sc.camera.exposure;
  const double t = index / sc.fps;
  out->blur_path_px = MaxImagePathPx(
      *sequence.camera(), out->depth_true_m, out->T_world_camera,
      ExposurePath(sc.camera, t, sc.seed, exposure.exposure_s, kPathSegments), kPathPixelStride);
  out->colour_subframes = SubframeCount(out->blur_path_px, exposure);
  if (out->colour_subframes == 1) return;
  std::vector<cv::Mat> colours;
  for (double offset : SubframeOffsets(exposure.exposure_s, out->colour_subframes)) {
    if (offset == 0.0) {
      colours.push_back(out->colour_clean);
      continue;
    }
    colours.push_back(RenderScene(sequence.GeometryAtTime(t + offset), *sequence.camera(),
                                  CameraPoseAt(sc.camera, t + offset, sc.seed))
                          .colour);
  }
  out->colour_clean = MeanColour(colours);
}

}  // namespace

SyntheticSequence::SyntheticSequence(Scenario scenario) : scenario_(std::move(scenario)) {
  const SensorParams& s = scenario_.sensor;
  camera_ = std::make_shared<PinholeCamera>(s.width, s.height, s.fx, s.fy, s.cx, s.cy);
  static_scene_ = BuildStaticScene(scenario_.room, scenario_.seed);
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
  const RenderedImages images = RenderScene(GeometryAt(index), *camera_, out.T_world_camera);
  out.colour_clean = images.colour;
  out.depth_true_m = images.depth_m;
  out.mask = images.mask;
  if (scenario_.camera.exposure.exposure_s > 0.0) BlurColour(*this, index, &out);
  out.dynamic_fraction =
      static_cast<double>(cv::countNonZero(images.mask)) / static_cast<double>(images.mask.total());
  out.frame.stamp_s = StampOf(index);
  out.frame.camera = camera_;
  ApplySensorModel(scenario_.sensor, scenario_.seed, index, out.colour_clean, images.depth_m,
                   &out.frame.colour, &out.depth_units);
  out.frame.depth_m = DepthFromScaledUint16(out.depth_units, scenario_.sensor.depth_scale);
  return out;
}

}  // namespace synth
}  // namespace dslam
