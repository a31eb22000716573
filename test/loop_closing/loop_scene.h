#pragma once
// A synthetic room for the loop detector tests, built by hand (no rendering): static places on a
// cylindrical wall with random 256-bit descriptors, keyframes on a circle looking outwards, map
// points with RGB-D measurements (y_camera with seeded noise and its covariance). Each "session"
// makes its own map points of the places it sees: a camera coming back in a new session makes
// the place a second time, with a few descriptor bits flipped and a drifted map frame.

#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "dslam/core/camera.h"
#include "dslam/tracking/map.h"
#include "place_recognition/random_descriptors.h"

namespace dslam {
namespace test {

/// Places seen by the keyframes: true positions [m, world] and one descriptor each.
struct PlaceSet {
  std::vector<Eigen::Vector3d> p_world_true;
  cv::Mat descriptors;  ///< one 1x32 row per place
  bool marked = true;   ///< their map points are verified static (else unmarked: people)
};

/// One making of map points: place index -> map point id, the map frame's drift and bit flips.
struct Session {
  std::map<int, PointId> point_of_place;
  Eigen::Isometry3d T_map_world = Eigen::Isometry3d::Identity();  ///< [m] drift of this session
  int flipped_bits = 0;
};

/// [m] The camera centre on a circle of radius `radius_m` at angle `theta` [rad], looking
/// outwards (optical z radial, y down = -world z).
inline Eigen::Isometry3d CirclePose(double theta, double radius_m) {
  const Eigen::Vector3d z(std::cos(theta), std::sin(theta), 0.0);
  const Eigen::Vector3d y(0.0, 0.0, -1.0);
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  T_world_camera.linear() << y.cross(z), y, z;
  T_world_camera.translation() = radius_m * z;
  return T_world_camera;
}

/// `n` places on a wall of radius `radius_m`, heights in +-`half_height_m`, random descriptors.
inline PlaceSet WallPlaces(int n, double radius_m, double half_height_m, std::mt19937* rng) {
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI),
      height(-half_height_m, half_height_m);
  PlaceSet places;
  for (int i = 0; i < n; ++i) {
    const double a = angle(*rng);
    places.p_world_true.emplace_back(radius_m * std::cos(a), radius_m * std::sin(a), height(*rng));
  }
  places.descriptors = RandomDescriptors(n, rng);
  return places;
}

/// The map being built and the truth of its keyframes.
struct LoopScene {
  PinholeCamera camera{640, 480, 525.0, 525.0, 319.5, 239.5};
  Map map;
  std::vector<Eigen::Isometry3d> T_world_camera_true;  ///< by keyframe id
  std::mt19937 rng{7};
  double sigma_xy_m = 0.002, sigma_z_m = 0.005;  ///< measurement noise, optical frame

  /// Adds a keyframe at true pose `T_true` (camera -> world) listing the places of each
  /// (set, session) pair it sees; returns its id. Its map pose is the session's drift times the
  /// truth (the first pair's session).
  int AddKeyFrame(int frame_index, const Eigen::Isometry3d& T_true,
                  const std::vector<std::pair<const PlaceSet*, Session*>>& seen) {
    KeyFrame keyframe;
    keyframe.frame_index = frame_index;
    keyframe.stamp_s = 0.1 * frame_index;
    keyframe.T_world_camera = seen.front().second->T_map_world * T_true;
    for (const auto& [places, session] : seen) {
      for (size_t i = 0; i < places->p_world_true.size(); ++i) {
        const Eigen::Vector3d y = T_true.inverse() * places->p_world_true[i];
        if (y.z() < 0.3 || !camera.InImage(camera.Project(y), 5.0)) continue;
        const PointId id = PointOf(*places, static_cast<int>(i), session);
        keyframe.points.push_back(id);
        keyframe.measurements.by_point[id] = Measure(y);
      }
    }
    T_world_camera_true.push_back(T_true);
    return map.AddKeyFrame(std::move(keyframe), KeyFrameMapLimits::Newest(1000)).id;
  }

 private:
  PointId PointOf(const PlaceSet& places, int i, Session* session) {
    const auto found = session->point_of_place.find(i);
    if (found != session->point_of_place.end()) return found->second;
    MapPoint point;
    point.p_world = session->T_map_world * places.p_world_true[i];
    point.descriptor = FlipBits(places.descriptors.row(i), session->flipped_bits, &rng);
    point.marked = places.marked;
    return session->point_of_place[i] = map.AddPoint(point);
  }

  PointMeasurement Measure(const Eigen::Vector3d& y_true) {
    std::normal_distribution<double> normal(0.0, 1.0);
    PointMeasurement m;
    m.y_camera = y_true + Eigen::Vector3d(sigma_xy_m * normal(rng), sigma_xy_m * normal(rng),
                                          sigma_z_m * normal(rng));
    m.covariance =
        Eigen::Vector3d(sigma_xy_m * sigma_xy_m, sigma_xy_m * sigma_xy_m, sigma_z_m * sigma_z_m)
            .asDiagonal();
    m.depth_mean_m = y_true.z();
    m.depth_sigma_m = sigma_z_m;
    return m;
  }
};

}  // namespace test
}  // namespace dslam
