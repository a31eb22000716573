#include "dslam/synth/sequence.h"

#include <cmath>
#include <utility>

#include "dslam/core/depth_conversion.h"
#include "dslam/synth/render.h"

namespace dslam {
namespace synth {

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
  const double t = index / scenario_.fps;
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
  out.dynamic_fraction =
      static_cast<double>(cv::countNonZero(images.mask)) / static_cast<double>(images.mask.total());
  out.frame.stamp_s = StampOf(index);
  out.frame.camera = camera_;
  ApplySensorModel(scenario_.sensor, scenario_.seed, index, images.colour, images.depth_m,
                   &out.frame.colour, &out.depth_units);
  out.frame.depth_m = DepthFromScaledUint16(out.depth_units, scenario_.sensor.depth_scale);
  return out;
}

}  // namespace synth
}  // namespace dslam
