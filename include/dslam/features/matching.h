#pragma once
// ORB descriptor matching: Hamming distance, guided search around predicted pixel positions
// (tracking against map points) and brute-force matching with a ratio test (relocalisation).

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "dslam/features/features.h"

namespace dslam {

/// Hamming distance [bits, 0..256] between two 32-byte ORB descriptors (1x32 CV_8UC1 rows).
int HammingDistance(const cv::Mat& a, const cv::Mat& b);
/// The same on the descriptors' 32 bytes at `a` and `b` (no checks; for inner loops).
int Hamming(const uchar* a, const uchar* b);

/// A map point projected into the current frame.
struct ProjectedPoint {
  Eigen::Vector2d uv_ideal;   ///< [px] predicted undistorted pixel (camera.Project(T_cw * p_w))
  cv::Mat descriptor;         ///< 1x32 CV_8UC1 representative descriptor of the map point
  int predicted_octave = -1;  ///< expected pyramid level from the point's distance; -1 = unknown
  /// [px] this point's search radius at octave 0; 0 = ProjectionSearchOptions::radius_px.
  double radius_px = 0.0;
};

/// Options of SearchByProjection (defaults after ORB-SLAM2's TH_HIGH and ratio).
struct ProjectionSearchOptions {
  double radius_px = 7.0;    ///< [px] search radius at octave 0; x scale^octave when predicted
  int max_distance = 100;    ///< [bits] accept only Hamming distance below this
  double ratio = 0.9;        ///< best < ratio * second best (different features) or rejected
  int octave_tolerance = 1;  ///< candidates' octave within predicted +- this (when predicted)
};

/// For every projected point, the index into frame.features of its match or -1. A candidate is a
/// feature whose uv_ideal lies within the radius (r * octave_scale[predicted_octave] when the
/// octave is predicted, else r; r is the point's radius_px when positive, else options.radius_px)
/// and, with a predicted octave, whose octave is within octave_tolerance. The best candidate must
/// pass max_distance and the ratio test. Each feature is matched at most once: when several points
/// pick the same feature, the one with the smallest distance keeps it and the others get -1.
std::vector<int> SearchByProjection(const std::vector<ProjectedPoint>& points,
                                    const FrameFeatures& frame,
                                    const ProjectionSearchOptions& options = {});

/// One descriptor correspondence.
struct DescriptorMatch {
  int query = -1;    ///< row in the query descriptors
  int train = -1;    ///< row in the train descriptors
  int distance = 0;  ///< [bits] Hamming distance
};

/// Brute-force matching of every query row against all train rows (relocalisation): keeps the
/// nearest train row when its distance is below max_distance and below ratio * the second nearest;
/// a train row is used at most once (the closest query keeps it). Sorted by query index.
std::vector<DescriptorMatch> MatchBruteForce(const cv::Mat& query, const cv::Mat& train,
                                             int max_distance = 100, double ratio = 0.8);

}  // namespace dslam
