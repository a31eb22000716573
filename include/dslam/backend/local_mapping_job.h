#pragma once
// One run of the back end's local mapping after a keyframe (paper Sec. V): static point
// determination over the window (Algorithm 1, window_static_points.h), then local bundle
// adjustment (local_bundle_adjustment.h), on a copy of the keyframe window. The copy lets
// tracking go on with the live map while the run works: the constructor copies and Apply writes
// the results back, both under the caller's map lock; Run needs no lock. Run on an untouched map,
// copy, run and apply give the same map as running in place.

#include <cstdint>
#include <unordered_map>

#include <Eigen/Core>

#include "dslam/core/config.h"
#include "dslam/tracking/frame_result.h"
#include "dslam/tracking/map.h"

namespace dslam {

class LocalMappingJob {
 public:
  /// Copies the window of `map` (Map::WindowCopy) and remembers each copied point's position
  /// and mark. `generation` identifies the map it came from (Slam's reset counter).
  LocalMappingJob(const Map& map, uint64_t generation);

  /// Static point determination (when static points are on),
  /// then local BA, on the copy. Fills status() but for window_keyframes.
  void Run(const Config& config);

  /// Writes the run's results to `map`: keyframe poses of the keyframes still in its window,
  /// positions of the points the run moved and the mark state of the points it unmarked, for
  /// the points still in it. Nothing when local BA was rejected and nothing was unmarked.
  void Apply(Map* map) const;

  const BackEndStatus& status() const { return status_; }
  uint64_t generation() const { return generation_; }
  /// Id of the newest keyframe of the copied window (-1: none).
  int newest_keyframe_id() const { return newest_keyframe_id_; }
  /// Whether Apply changed keyframe poses (local BA ran and was applied).
  bool moved_keyframes() const { return status_.ran && !status_.ba_rejected; }

 private:
  struct PointBefore {
    Eigen::Vector3d p_world;
    bool marked;
  };

  Map window_;
  uint64_t generation_;
  int newest_keyframe_id_ = -1;
  std::unordered_map<PointId, PointBefore> before_;
  BackEndStatus status_;
};

}  // namespace dslam
