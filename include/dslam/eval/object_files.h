#pragma once
// Reading the moving-object files of the object measurement (object_metrics.h): the synthetic
// truth objects.txt that dslam_synth writes (world frame of groundtruth.txt) and the estimates
// that `dslam_run_dataset --objects` writes (the trajectory's frame). Both: one line per frame and
// object, whitespace-separated, '#' comment lines and blank lines skipped.

#include <istream>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace dslam {

/// One true moving object in one frame: `timestamp id x y z vx vy vz pixel_share`.
struct TruthObject {
  double stamp_s = 0.0;                                    ///< [s] frame stamp
  int id = 0;                                              ///< object (mask) id
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();    ///< [m] centroid, world frame
  Eigen::Vector3d velocity_mps = Eigen::Vector3d::Zero();  ///< [m/s] body velocity, world frame
  double pixel_share = 0.0;  ///< [-] share of the image the object's mask covers
};

/// One estimated moving object in one frame: `timestamp id x y z vx vy vz ex ey ez`.
struct EstimatedObject {
  double stamp_s = 0.0;                                    ///< [s] frame stamp
  int id = 0;                                              ///< track id
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();    ///< [m] centroid, estimate's frame
  Eigen::Vector3d velocity_mps = Eigen::Vector3d::Zero();  ///< [m/s] estimate's frame
  Eigen::Vector3d extent_m = Eigen::Vector3d::Zero();      ///< [m] full axis-aligned size
};

/// Parses truth lines from `in`; `name` (the file's name) starts each message. Throws
/// std::runtime_error naming the line when a line has fewer than 9 numbers or a non-finite one,
/// and naming the file when an id is not a whole number in [0, 2^31).
std::vector<TruthObject> ParseTruthObjects(std::istream& in, const std::string& name);

/// Reads a truth file (objects.txt). Throws std::runtime_error when it cannot be opened.
std::vector<TruthObject> ReadTruthObjects(const std::string& path);

/// Parses estimate lines from `in` (11 numbers each); errors as ParseTruthObjects.
std::vector<EstimatedObject> ParseEstimatedObjects(std::istream& in, const std::string& name);

/// Reads an estimate file. Throws std::runtime_error when it cannot be opened.
std::vector<EstimatedObject> ReadEstimatedObjects(const std::string& path);

}  // namespace dslam
