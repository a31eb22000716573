#include "objects_output.h"

#include <cstdio>
#include <stdexcept>

#include "dslam/core/stopwatch.h"

namespace dslam {
namespace tools {

ObjectsOutput::ObjectsOutput(const std::string& path, const Config& config, WorkerMode mode)
    : path_(path), out_(path), objects_(config), worker_(mode, 2) {
  if (!out_) throw std::runtime_error("cannot write " + path);
  out_ << "# dslam moving objects, odometry world frame (the first frame's optical frame)\n"
          "# timestamp id x y z vx vy vz ex ey ez\n";
}

void ObjectsOutput::Add(const RgbdFrame& frame, const FrameResult& result) {
  const Stopwatch watch;
  // The frame's images are shared, not copied: nothing writes to a frame after ProcessFrame.
  worker_.Post([this, frame, result] { Track(frame, result); });
  add_times_ms_.push_back(watch.ElapsedMs());
}

void ObjectsOutput::Track(const RgbdFrame& frame, const FrameResult& result) {
  const Stopwatch watch;
  const std::vector<TrackedObject> objects = objects_.Process(frame, result);
  times_ms_.push_back(watch.ElapsedMs());
  for (const TrackedObject& o : objects) {
    char line[256];
    std::snprintf(line, sizeof(line), "%.6f %d %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f\n",
                  result.stamp_s, o.id, o.position_world.x(), o.position_world.y(),
                  o.position_world.z(), o.velocity_world.x(), o.velocity_world.y(),
                  o.velocity_world.z(), o.extent.x(), o.extent.y(), o.extent.z());
    out_ << line;
    ++object_frames_;
  }
}

void ObjectsOutput::Close() {
  worker_.Wait();
  out_.flush();
  if (!out_) throw std::runtime_error("error while writing " + path_);
}

}  // namespace tools
}  // namespace dslam
