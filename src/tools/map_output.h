#pragma once
// dslam_run_dataset --map / --map-unmasked: static maps (StaticMapper, part mapping) fed by Slam
// as its keyframe observers, written as PCD files (x y z rgb) in the trajectory's frame (the
// odometry world frame: the first frame's optical frame). The unmasked map is the same fusion of
// the same run without dynamic masks and without the free-space check: the static-world
// baseline. --grid writes the masked map's occupancy grid (occupancy_grid.h) as map_server's
// YAML and PGM pair, its up the config's grid.up_* in the first frame's optical frame; --octomap
// the masked map as an OctoMap binary file (octomap_file.h) in the trajectory's frame.

#include <memory>
#include <string>
#include <vector>

#include "dslam/backend/keyframe_observer.h"
#include "dslam/core/config.h"
#include "dslam/eval/json_writer.h"
#include "dslam/mapping/octomap_file.h"
#include "dslam/mapping/static_mapper.h"

namespace dslam {
namespace tools {

/// The maps asked for (an empty path: that map is not built).
class MapOutput {
 public:
  /// `config`: the run's (config.map for both maps; the unmasked one with dynamic_masks and
  /// free_space_check off; config.grid for the grid). `grid_path`: the grid's YAML (its PGM
  /// beside it), `octomap_path`: the OctoMap file; the masked map is built for them also
  /// without `masked_path`.
  MapOutput(const std::string& masked_path, const std::string& unmasked_path,
            const std::string& grid_path, const std::string& octomap_path, const Config& config);

  /// The mappers, for Slam's constructor (empty when no map is asked for).
  std::vector<std::shared_ptr<KeyFrameObserver>> Observers() const;

  /// Fuses the keyframes still in the window and writes the files; call after
  /// Slam::WaitForBackEnd. Throws std::runtime_error when a file cannot be written.
  void Write();

  /// One line per map written (points, keyframes, transient points and voxels removed) and one
  /// for the grid.
  void Print() const;

  /// Adds map_points, map_transient_points, map_carved_voxels and map_unmasked_points.
  void AddTo(JsonObject* json) const;

 private:
  std::string masked_path_, unmasked_path_, grid_path_, octomap_path_;
  Config config_;
  std::shared_ptr<StaticMapper> masked_, unmasked_;
  OccupancyGrid grid_;
  OctoMapStats octomap_;
  size_t masked_points_ = 0, unmasked_points_ = 0;
};

}  // namespace tools
}  // namespace dslam
