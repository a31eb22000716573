// Ground truth of the moving objects (object_truth.h).
#include "dslam/synth/object_truth.h"

#include <cstdio>
#include <map>
#include <stdexcept>

#include "dslam/synth/writer.h"

namespace dslam {
namespace synth {

Eigen::Vector3d ObjectVelocityAt(const Scenario& scenario, uint16_t id, double t_s) {
  const size_t walkers = scenario.walkers.size(), boxes = scenario.boxes.size();
  const size_t sheets = scenario.sheets.size();
  if (id == 0 || id > walkers + boxes + sheets) {
    throw std::out_of_range("scenario '" + scenario.name + "' has no moving object with id " +
                            std::to_string(id));
  }
  const size_t k = id - 1;
  if (k < walkers) return WalkerVelocityAt(scenario.walkers[k], t_s);
  if (k < walkers + boxes) return MovingBoxVelocityAt(scenario.boxes[k - walkers], t_s);
  return Eigen::Vector3d::Zero();  // a sheet hangs from its fixed top edge
}

std::vector<ObjectTruth> VisibleObjects(const SyntheticSequence& sequence,
                                        const SyntheticFrame& frame) {
  const PinholeCamera& camera = *sequence.camera();
  std::map<uint16_t, ObjectTruth> objects;
  for (int v = 0; v < frame.mask.rows; ++v) {
    for (int u = 0; u < frame.mask.cols; ++u) {
      const uint16_t id = frame.mask.at<uint16_t>(v, u);
      if (id == 0) continue;
      ObjectTruth& object = objects[id];
      object.id = id;
      ++object.pixels;
      // Sum of camera-frame points; the mean is moved to the world below (an affine map).
      object.centroid_world_m +=
          camera.BackProject(Eigen::Vector2d(u, v), frame.depth_true_m.at<float>(v, u));
    }
  }
  const double t_s = frame.index / sequence.scenario().fps;
  std::vector<ObjectTruth> out;
  for (auto& [id, object] : objects) {
    object.centroid_world_m = frame.T_world_camera * (object.centroid_world_m / object.pixels);
    object.pixel_share = static_cast<double>(object.pixels) / frame.mask.total();
    object.velocity_world_mps = ObjectVelocityAt(sequence.scenario(), id, t_s);
    out.push_back(object);
  }
  return out;
}

std::string ObjectTruthHeader(const Scenario& scenario) {
  return "# moving objects seen in each frame: ground truth of dslam_synth " + scenario.name +
         " seed " + std::to_string(scenario.seed) +
         "\n# world frame of groundtruth.txt; x y z [m]: mean of the noise-free 3D points of the "
         "object's mask pixels\n# vx vy vz [m/s]: velocity of the object's body (walker: floor "
         "point, 0 while pausing; box: centre; sheet: 0)\n# pixel_share: share of the image its "
         "mask covers; id: mask id\n# timestamp id x y z vx vy vz pixel_share\n";
}

std::string FormatObjectTruth(double stamp_s, const ObjectTruth& o) {
  char line[256];
  const Eigen::Vector3d& p = o.centroid_world_m;
  const Eigen::Vector3d& v = o.velocity_world_mps;
  std::snprintf(line, sizeof(line), "%s %d %.6f %.6f %.6f %.6f %.6f %.6f %.6f",
                FormatStamp(stamp_s).c_str(), static_cast<int>(o.id), p.x(), p.y(), p.z(), v.x(),
                v.y(), v.z(), o.pixel_share);
  return line;
}

}  // namespace synth
}  // namespace dslam
